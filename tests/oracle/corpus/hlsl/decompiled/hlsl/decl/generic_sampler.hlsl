// ps_3_0 shader decompiled by ps30
sampler2D s2d : register(s0);
samplerCUBE sCube : register(s1);
sampler3D sVol : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(s2d, texcoord0.xy) + texCUBE(sCube, texcoord1.xyz);
    oC0 = r0 + tex3D(sVol, texcoord1.xyz);
    return oC0;
}
