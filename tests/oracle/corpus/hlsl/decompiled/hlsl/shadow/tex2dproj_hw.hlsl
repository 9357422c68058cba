// ps_3_0 shader decompiled by ps30
float4 ambient : register(c1);
float4 lightColor : register(c0);
sampler2D baseSampler : register(s0);
sampler2D shadowSampler : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = (saturate(texcoord2.x) * lightColor) * tex2Dproj(shadowSampler, texcoord1).x + ambient;
    oC0 = r0 * tex2D(baseSampler, texcoord0.xy);
    return oC0;
}
