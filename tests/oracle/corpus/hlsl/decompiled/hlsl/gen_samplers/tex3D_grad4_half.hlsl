// ps_3_0 shader decompiled by ps30
float4 k : register(c0);
sampler3D s : register(s5);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    oC0 = tex3Dgrad(s, texcoord0.xyz, texcoord1.xyz, texcoord2.xyz).zyxw * k.x;
    return oC0;
}
