// ps_3_0 shader decompiled by ps30
float4 Color : register(c0);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    oC0 = Color;
    return oC0;
}
