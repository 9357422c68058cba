// ps_3_0 shader decompiled by ps30
float Knee : register(c1);
float MiddleGray : register(c2);
float Threshold : register(c0);
sampler2D SceneSampler : register(s0);
sampler2D LumSampler : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.x = 1.0 / (tex2D(LumSampler, float2(0.5, 0.5)).x + 0.001);
    r0.xyz = (r0.x * MiddleGray) * tex2D(SceneSampler, texcoord0.xy).xyz;
    r2.x = max(r0.x, max(r0.y, r0.z));
    r0.w = r2.x - Threshold;
    r2.y = max((r0.w + Knee), 0.0);
    r3.x = min((Knee + Knee), r2.y);
    r1.x = r3.x * r3.x;
    r1.y = 1.0 / (Knee * 4.0 + 1.0e-5);
    r2.y = max((r1.y * r1.x), r0.w);
    r0.w = ((r2.x - 1.0e-5) >= 0.0 ? (1.0 / r2.x) : 100000.0) * r2.y;
    oC0.xyz = r0.w * r0.xyz;
    oC0.w = 1.0;
    return oC0;
}
