// ps_3_0 shader decompiled by ps30
float detailScale : register(c0);
sampler2D baseSampler : register(s0);
sampler2D lightmapSampler : register(s1);
sampler2D detailSampler : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = tex2D(detailSampler, (detailScale * texcoord0.xy));
    r2 = tex2D(baseSampler, texcoord0.xy);
    oC0.w = r2.w;
    oC0.xyz = (r0.xyz * (tex2D(lightmapSampler, texcoord1.xy).xyz * r2.xyz)) * 4.0;
    return oC0;
}
