// ps_3_0 shader decompiled by ps30
float4 w : register(c0);
int4 outerCount : register(i0);
int4 innerCount : register(i1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0 = 0.0;
    r1.x = 0.0;
    for (int n0 = 0; n0 < outerCount.x; n0++) {
        r1.x = r1.x + 1.0;
        r2 = r0;
        r1.y = 0.0;
        for (int n1 = 0; n1 < innerCount.x; n1++) {
            r3 = (texcoord0 * r1.x + r1.y) * 0.15915494 + 0.25;
            r3 = frac(r3) * 6.2831855 - 3.1415927;
            r3 = r3 * r3;
            r4 = r3 * (r3 * -2.523985e-7 + 2.47609e-5) - 0.0013888397;
            r4 = r3 * (r3 * r4 + 0.04166664) - 0.5;
            r3 = r3 * r4 + 1.0;
            r2 = r3 * w + r2;
            r1.y = r1.y + 1.0;
        }
        r0 = r2;
    }
    oC0 = r0;
    return oC0;
}
