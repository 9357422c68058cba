// ps_3_0 shader decompiled by ps30
float4 a[4] : register(c0);
float4 b[4] : register(c4);
float sel : register(c8);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    if (sel < texcoord0.w) {
        r0 = 0.0;
        r1.x = 0.0;
        for (int n0 = 0; n0 < int4(4, 0, 0, 0).x; n0++) {
            r2 = r1.x + float4(-0.0, -1.0, -2.0, -3.0);
            r1.y = 0.0;
            r3 = -abs(r2.z) >= 0.0 ? a[2] : (-abs(r2.y) >= 0.0 ? a[1] : (-abs(r2.x) >= 0.0 ? a[0] : r1.y));
            r2 = -abs(r2.w) >= 0.0 ? a[3] : r3;
            r0 = r2 * texcoord0 + r0;
            r1.x = r1.x + 1.0;
        }
        oC0 = r0;
    } else {
        r0 = 0.0;
        r1.x = 0.0;
        for (int n0 = 0; n0 < int4(4, 0, 0, 0).x; n0++) {
            r2 = r1.x + float4(-0.0, -1.0, -2.0, -3.0);
            r1.y = 0.0;
            r3 = -abs(r2.z) >= 0.0 ? b[2] : (-abs(r2.y) >= 0.0 ? b[1] : (-abs(r2.x) >= 0.0 ? b[0] : r1.y));
            r2 = -abs(r2.w) >= 0.0 ? b[3] : r3;
            r0 = r2 * -texcoord0 + r0;
            r1.x = r1.x + 1.0;
        }
        oC0 = r0;
    }
    return oC0;
}
