// ps_3_0 shader decompiled by ps30
float4 arr[8] : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0 = 0.0;
    r1.x = 0.0;
    for (int n0 = 0; n0 < int4(8, 0, 0, 0).x; n0++) {
        r2 = r1.x + float4(-0.0, -1.0, -2.0, -3.0);
        r3 = r1.x + float4(-4.0, -5.0, -6.0, -7.0);
        r1.y = 0.0;
        r4 = -abs(r2.z) >= 0.0 ? arr[2] : (-abs(r2.y) >= 0.0 ? arr[1] : (-abs(r2.x) >= 0.0 ? arr[0] : r1.y));
        r2 = -abs(r2.w) >= 0.0 ? arr[3] : r4;
        r2 = -abs(r3.y) >= 0.0 ? arr[5] : (-abs(r3.x) >= 0.0 ? arr[4] : r2);
        r2 = -abs(r3.w) >= 0.0 ? arr[7] : (-abs(r3.z) >= 0.0 ? arr[6] : r2);
        r0 = r2 * texcoord0.x + r0;
        r1.x = r1.x + 1.0;
    }
    oC0 = r0;
    return oC0;
}
