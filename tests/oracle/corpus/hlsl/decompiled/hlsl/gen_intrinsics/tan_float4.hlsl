// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = frac((texcoord0 * 0.15915494 + 0.25)) * 6.2831855 - 3.1415927;
    r0 = r0 * r0;
    r1 = r0 * (r0 * (r0 * -2.523985e-7 + 2.47609e-5) - 0.0013888397) + 0.04166664;
    r0 = r0 * (r0 * r1 - 0.5) + 1.0;
    r1 = frac((texcoord0 * 0.15915494 + 0.5)) * 6.2831855 - 3.1415927;
    r1 = r1 * r1;
    r2 = r1 * (r1 * (r1 * -2.523985e-7 + 2.47609e-5) - 0.0013888397) + 0.04166664;
    r1 = r1 * (r1 * r2 - 0.5) + 1.0;
    r2.x = 1.0 / r1.x;
    r2.y = 1.0 / r1.y;
    r2.z = 1.0 / r1.z;
    r2.w = 1.0 / r1.w;
    oC0 = r0 * r2;
    return oC0;
}
