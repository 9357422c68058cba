// ps_3_0 shader decompiled by ps30
row_major float4x4 ViewProj : register(c4);
row_major float4x4 World : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = mul(texcoord0, World);
    oC0 = mul(r0, ViewProj);
    return oC0;
}
