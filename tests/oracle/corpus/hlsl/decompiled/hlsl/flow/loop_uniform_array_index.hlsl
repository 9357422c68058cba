// ps_3_0 shader decompiled by ps30
float4 coeffs[12] : register(c0);
int4 count : register(i0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    r0 = 0.0;
    r1.x = 0.0;
    for (int n0 = 0; n0 < count.x; n0++) {
        r2 = r1.x + float4(-0.0, -1.0, -2.0, -3.0);
        r3 = r1.x + float4(-4.0, -5.0, -6.0, -7.0);
        r4 = r1.x + float4(-8.0, -9.0, -10.0, -11.0);
        r5 = -abs(r2.x) >= 0.0 ? coeffs[0] : 0.0;
        r5 = -abs(r2.z) >= 0.0 ? coeffs[2] : (-abs(r2.y) >= 0.0 ? coeffs[1] : r5);
        r2 = -abs(r2.w) >= 0.0 ? coeffs[3] : r5;
        r2 = -abs(r3.y) >= 0.0 ? coeffs[5] : (-abs(r3.x) >= 0.0 ? coeffs[4] : r2);
        r2 = -abs(r3.w) >= 0.0 ? coeffs[7] : (-abs(r3.z) >= 0.0 ? coeffs[6] : r2);
        r2 = -abs(r4.y) >= 0.0 ? coeffs[9] : (-abs(r4.x) >= 0.0 ? coeffs[8] : r2);
        r2 = -abs(r4.w) >= 0.0 ? coeffs[11] : (-abs(r4.z) >= 0.0 ? coeffs[10] : r2);
        r0 = r2 * texcoord0 + r0;
        r1.x = r1.x + 1.0;
    }
    oC0 = r0;
    return oC0;
}
