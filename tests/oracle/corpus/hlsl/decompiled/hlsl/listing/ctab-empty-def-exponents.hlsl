// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = texcoord0.xyxy * (1.0e-10) + float4(1.0e20, -0.5, 123456790.0, 3.1415927);
    return oC0;
}
