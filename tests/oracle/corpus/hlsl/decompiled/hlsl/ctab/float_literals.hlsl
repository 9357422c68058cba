// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = texcoord0.yxwz * float4(0.7, 0.95, 0.33333334, 6.0221406e23) + (texcoord0 * float4(0.33333334, 3.1415927, 1.0e-7, 12345678.0) + (float4(-0.0, 0.1, 1.0e20, -0.0025) * texcoord0.wzyx));
    return oC0;
}
