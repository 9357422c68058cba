// Lightmapped world geometry: base * lightmap * 2 with a detail texture.
sampler2D baseSampler : register(s0);
sampler2D lightmapSampler : register(s1);
sampler2D detailSampler : register(s2);
float detailScale = 8.0;

float4 main(float2 uvBase : TEXCOORD0, float2 uvLight : TEXCOORD1) : COLOR
{
    float4 base = tex2D(baseSampler, uvBase);
    float3 lm = tex2D(lightmapSampler, uvLight).rgb * 2;
    float3 detail = tex2D(detailSampler, uvBase * detailScale).rgb * 2;
    return float4(base.rgb * lm * detail, base.a);
}
