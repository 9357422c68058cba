// Retro filters chosen by an int uniform: sepia, pixelate, posterize.
sampler2D src;
int    filterMode;
float2 resolution;
float  levels = 5;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float2 t = uv;
    if (filterMode == 1)
        t = (floor(uv * resolution / 8) + 0.5) * 8 / resolution;
    float3 c = tex2D(src, t).rgb;
    if (filterMode == 0)
        c = float3(dot(c, float3(0.393, 0.769, 0.189)), dot(c, float3(0.349, 0.686, 0.168)), dot(c, float3(0.272, 0.534, 0.131)));
    else if (filterMode == 2)
        c = floor(c * levels) / levels;
    return float4(c, 1);
}
