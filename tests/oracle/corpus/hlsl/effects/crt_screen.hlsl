// CRT: barrel distortion, shadow mask by VPOS column, scanlines, vignette.
sampler2D frameBuf;
float2 srcSize;
float  curvature = 0.1;

float4 main(float2 uv : TEXCOORD0, float2 pix : VPOS) : COLOR
{
    float2 c = uv * 2 - 1;
    c *= 1 + dot(c, c) * curvature;
    float2 t = c * 0.5 + 0.5;
    if (any(t < 0) || any(t > 1)) return float4(0, 0, 0, 1);
    float3 col = tex2D(frameBuf, t).rgb;
    float scan = 0.75 + 0.25 * sin(t.y * srcSize.y * 6.2831853);
    float3 mask = float3(fmod(pix.x, 3) < 1, fmod(pix.x + 1, 3) < 1, fmod(pix.x + 2, 3) < 1) * 0.5 + 0.5;
    return float4(col * scan * mask * (1 - dot(c, c) * 0.2), 1);
}
