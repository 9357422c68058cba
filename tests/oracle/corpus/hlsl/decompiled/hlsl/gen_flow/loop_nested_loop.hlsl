// ps_3_0 shader decompiled by ps30
float4 w[4] : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0 = 0.0;
    r1.x = 0.0;
    for (int n0 = 0; n0 < int4(4, 0, 0, 0).x; n0++) {
        r2 = r1.x + float4(-0.0, -1.0, -2.0, -3.0);
        r3 = -abs(r2.z) >= 0.0 ? w[2] : (-abs(r2.y) >= 0.0 ? w[1] : (-abs(r2.x) >= 0.0 ? w[0] : 0.0));
        r2 = (-abs(r2.w) >= 0.0 ? w[3] : r3) * texcoord0;
        r3 = r0;
        r1.y = 0.0;
        for (int n1 = 0; n1 < int4(3, 0, 0, 0).x; n1++) {
            r3 = r2 * r1.y + r3;
            r1.y = r1.y + 1.0;
        }
        r0 = r3;
        r1.x = r1.x + 1.0;
    }
    oC0 = r0;
    return oC0;
}
