// ps_3_0 shader decompiled by ps30
sampler2D flatS : register(s0);
sampler2D rampS : register(s1);
sampler3D volS : register(s2);
samplerCUBE cubeS : register(s3);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(flatS, texcoord0.xy) + tex2D(rampS, texcoord0.xy);
    r0 = r0 + tex3D(volS, texcoord0.xyz);
    oC0 = r0 + texCUBE(cubeS, texcoord0.xyz);
    return oC0;
}
