// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
samplerCUBE sky : register(s1);

float4 main(float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = texCUBE(sky, texcoord2.xyz);
    return oC0;
}
