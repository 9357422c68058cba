// Final output: gamma, then an ordered 4x4 Bayer dither from VPOS.
sampler2D linearScene;
float invGamma = 0.4545;

static const float bayer[16] = { 0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5 };

float4 main(float2 uv : TEXCOORD0, float2 pos : VPOS) : COLOR
{
    float3 c = pow(tex2D(linearScene, uv).rgb, invGamma);
    int2 p = (int2)fmod(pos, 4);
    float d = (bayer[p.y * 4 + p.x] + 0.5) / 16 - 0.5;
    return float4(c + d / 255, 1);
}
