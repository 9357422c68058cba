// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    oC0 = texcoord0;
    return oC0;
}
