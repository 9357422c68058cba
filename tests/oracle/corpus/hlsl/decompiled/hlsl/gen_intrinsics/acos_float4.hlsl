// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = (abs(texcoord0) * -0.0187293 + 0.074261) * abs(texcoord0) - 0.2121144;
    r1 = 1.0 - abs(texcoord0);
    r2.x = 1.0 / rsqrt(abs(r1.x));
    r2.y = 1.0 / rsqrt(abs(r1.y));
    r1.x = rsqrt(abs(r1.z));
    r2.w = 1.0 / rsqrt(abs(r1.w));
    r2.z = 1.0 / r1.x;
    r0 = (r0 * abs(texcoord0) + 1.5707288) * r2;
    oC0 = (r0 * -2.0 + 3.1415927) * (texcoord0 >= 0.0 ? 0.0 : 1.0) + r0;
    return oC0;
}
