// ps_3_0 shader decompiled by ps30

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    oC0 = 0.0;
    return oC0;
}
