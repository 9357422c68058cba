// Unsharp mask with a clamp on the added detail.
sampler2D frameTex;
float2 px;
float amount = 0.6;
float limit = 0.1;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float3 c = tex2D(frameTex, uv).rgb;
    float3 blur = (tex2D(frameTex, uv + float2(px.x, 0)).rgb + tex2D(frameTex, uv - float2(px.x, 0)).rgb
                 + tex2D(frameTex, uv + float2(0, px.y)).rgb + tex2D(frameTex, uv - float2(0, px.y)).rgb) * 0.25;
    float3 detail = clamp((c - blur) * amount, -limit, limit);
    return float4(c + detail, 1);
}
