// One Kawase iteration: four diagonal taps at distance (k + 0.5).
sampler2D src;
float4 pixel; // xy = 1/size, z = iteration

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float2 d = pixel.xy * (pixel.z + 0.5);
    float4 c = tex2D(src, uv + float2( d.x,  d.y));
    c += tex2D(src, uv + float2(-d.x,  d.y));
    c += tex2D(src, uv + float2( d.x, -d.y));
    c += tex2D(src, uv + float2(-d.x, -d.y));
    return c * 0.25;
}
