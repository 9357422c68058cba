// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    oC0 = texcoord0.xyzx * float4(0.017453292, 0.017453292, 0.017453292, 0.0) + float4(0.0, 0.0, 0.0, 1.0);
    return oC0;
}
