// ps_3_0 shader decompiled by ps30
sampler3D s : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    oC0 = tex3Dbias(s, texcoord0);
    return oC0;
}
