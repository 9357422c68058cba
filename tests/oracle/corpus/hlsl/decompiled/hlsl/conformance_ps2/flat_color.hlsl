// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30

void main(float4 color0 : COLOR0, float4 color1 : COLOR1, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1)
{
    oC0 = 0;
    oC1 = 0;
    oC0 = color0;
    oC1 = color1;
}
