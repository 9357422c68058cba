// ps_3_0 shader decompiled by ps30
sampler2D DiffuseSampler : register(s0);
samplerCUBE EnvSampler : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    oC0 = texCUBE(EnvSampler, texcoord1.xyz) * 0.25 + tex2D(DiffuseSampler, texcoord0.xy);
    return oC0;
}
