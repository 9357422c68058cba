// Scene + bloom combine, exponential exposure, vignette, sRGB encode.
sampler2D Scene : register(s0);
sampler2D Bloom : register(s1);
sampler2D AdaptedLum : register(s2);
float BloomIntensity = 0.8;
float KeyValue = 0.18;
float VignetteAmount;

float3 LinearToSRGB(float3 c)
{
    float3 lo = c * 12.92;
    float3 hi = 1.055 * pow(c, 1.0 / 2.4) - 0.055;
    return c <= 0.0031308 ? lo : hi;
}

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float adapted = tex2D(AdaptedLum, 0.5).r;
    float exposure = KeyValue / max(adapted, 0.0001);
    float3 c = tex2D(Scene, uv).rgb + tex2D(Bloom, uv).rgb * BloomIntensity;
    c = 1 - exp(-c * exposure);
    float2 d = uv - 0.5;
    c *= 1 - dot(d, d) * VignetteAmount;
    return float4(LinearToSRGB(saturate(c)), 1);
}
