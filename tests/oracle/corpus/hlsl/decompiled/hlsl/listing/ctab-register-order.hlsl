// ps_3_0 shader decompiled by ps30
float4 x[2] : register(c3);
float4 y : register(c0);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = x[1] + y;
    return oC0;
}
