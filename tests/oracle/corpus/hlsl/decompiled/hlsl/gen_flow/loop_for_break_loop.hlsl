// ps_3_0 shader decompiled by ps30
float4 w[8] : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0 = 0.0;
    r1.x = 0.0;
    for (int n0 = 0; n0 < int4(8, 0, 0, 0).x; n0++) {
        r2 = r1.x + float4(-0.0, -1.0, -2.0, -3.0);
        r3 = r1.x + float4(-4.0, -5.0, -6.0, -7.0);
        r1.y = 0.0;
        r4 = -abs(r2.z) >= 0.0 ? w[2] : (-abs(r2.y) >= 0.0 ? w[1] : (-abs(r2.x) >= 0.0 ? w[0] : r1.y));
        r2 = -abs(r3.x) >= 0.0 ? w[4] : (-abs(r2.w) >= 0.0 ? w[3] : r4);
        r2 = -abs(r3.z) >= 0.0 ? w[6] : (-abs(r3.y) >= 0.0 ? w[5] : r2);
        r2 = (-abs(r3.w) >= 0.0 ? w[7] : r2) * texcoord0 + r0;
        if (texcoord1.x < r2.x) {
            r0 = r2;
            if (1.0 != -1.0) break;
        }
        r1.x = r1.x + 1.0;
        r0 = r2;
    }
    oC0 = r0;
    return oC0;
}
