// Lens chromatic aberration with film grain and scanlines.
sampler2D image : register(s0);
sampler2D grain : register(s1);
float caStrength;
float grainAmount;
float frame;
float scanlines;

float4 main(float2 uv : TEXCOORD0, float2 vpos : VPOS) : COLOR
{
    float2 d = uv - 0.5;
    float r = tex2D(image, uv + d * caStrength).r;
    float g = tex2D(image, uv).g;
    float b = tex2D(image, uv - d * caStrength).b;
    float n = tex2D(grain, vpos / 64 + frac(frame * float2(0.37, 0.71))).r - 0.5;
    float s = 1 - scanlines * (fmod(vpos.y, 2) < 1);
    return float4((float3(r, g, b) + n * grainAmount) * s, 1);
}
