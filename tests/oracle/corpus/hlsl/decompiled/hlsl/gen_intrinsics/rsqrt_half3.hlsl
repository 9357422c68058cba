// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    oC0.x = rsqrt(abs(texcoord0.x));
    oC0.y = rsqrt(abs(texcoord0.y));
    oC0.z = rsqrt(abs(texcoord0.z));
    oC0.w = 1.0;
    return oC0;
}
