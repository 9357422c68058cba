// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30

float4 main(float4 color0 : COLOR0, float4 color1 : COLOR1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = (color0 - color1);
    return oC0;
}
