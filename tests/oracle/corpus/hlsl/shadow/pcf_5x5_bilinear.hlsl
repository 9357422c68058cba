// 5x5 PCF with a manual bilinear weight on the compare results (smooth edges).
sampler2D shadowTex;
float4 shadowTexel;   // x = 1/size, y = size

float SampleCmp(float2 uv, float z) { return step(z, tex2D(shadowTex, uv).r); }

float ShadowBilinear(float2 uv, float z)
{
    float2 f = frac(uv * shadowTexel.y);
    float2 base = uv - f * shadowTexel.x;
    float a = SampleCmp(base, z);
    float b = SampleCmp(base + float2(shadowTexel.x, 0), z);
    float c = SampleCmp(base + float2(0, shadowTexel.x), z);
    float d = SampleCmp(base + shadowTexel.xx, z);
    return lerp(lerp(a, b, f.x), lerp(c, d, f.x), f.y);
}

float4 main(float4 sc : TEXCOORD0) : COLOR
{
    float3 p = sc.xyz / sc.w;
    float s = 0;
    [unroll] for (int j = -2; j <= 2; j++)
        [unroll] for (int i = -2; i <= 2; i++)
            s += ShadowBilinear(p.xy + float2(i, j) * shadowTexel.x, p.z);
    return s / 25;
}
