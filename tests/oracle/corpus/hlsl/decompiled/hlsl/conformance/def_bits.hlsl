// ps_3_0 shader decompiled by ps30
float4 scale : register(c0);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = scale * float4(0.0, -0.0, 1.1754944e-38, 0.5);
    return oC0;
}
