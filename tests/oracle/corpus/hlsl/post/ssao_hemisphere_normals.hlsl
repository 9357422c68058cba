// Normal-oriented hemisphere SSAO with view-space positions from a G-buffer.
sampler2D posVS  : register(s0);
sampler2D nrmVS  : register(s1);
sampler2D noise  : register(s2);
float4x4 projection;
float2 noiseScale;
float radius = 0.5;
float bias = 0.025;
float3 samples[16];

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float3 P = tex2D(posVS, uv).xyz;
    float3 N = normalize(tex2D(nrmVS, uv).xyz);
    float3 rv = normalize(tex2D(noise, uv * noiseScale).xyz);
    float3 T = normalize(rv - N * dot(rv, N));
    float3x3 TBN = float3x3(T, cross(N, T), N);
    float occ = 0;
    [loop]
    for (int i = 0; i < 16; ++i)
    {
        float3 s = P + mul(samples[i], TBN) * radius;
        float4 o = mul(float4(s, 1), projection);
        o.xy = o.xy / o.w * float2(0.5, -0.5) + 0.5;
        float sd = tex2Dlod(posVS, float4(o.xy, 0, 0)).z;
        float range = smoothstep(0, 1, radius / abs(P.z - sd));
        occ += (sd >= s.z + bias ? 1.0 : 0.0) * range;
    }
    return 1 - occ / 16;
}
