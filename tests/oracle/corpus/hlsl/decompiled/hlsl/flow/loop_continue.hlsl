// ps_3_0 shader decompiled by ps30
float4 data[8] : register(c0);
float4 mask : register(c8);

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
        r1.z = -abs(r2.x) >= 0.0 ? data[0].w : r1.y;
        r1.z = -abs(r2.z) >= 0.0 ? data[2].w : (-abs(r2.y) >= 0.0 ? data[1].w : r1.z);
        r1.z = -abs(r3.x) >= 0.0 ? data[4].w : (-abs(r2.w) >= 0.0 ? data[3].w : r1.z);
        r1.z = -abs(r3.z) >= 0.0 ? data[6].w : (-abs(r3.y) >= 0.0 ? data[5].w : r1.z);
        r1.z = (-abs(r3.w) >= 0.0 ? data[7].w : r1.z) - mask.x;
        r1.w = r1.x + 1.0;
        r2.x = r1.z >= 0.0 ? r1.x : r1.w;
        r3 = r2.x + float4(-0.0, -1.0, -2.0, -3.0);
        r2 = r2.x + float4(-4.0, -5.0, -6.0, -7.0);
        r4 = -abs(r3.z) >= 0.0 ? data[2] : (-abs(r3.y) >= 0.0 ? data[1] : (-abs(r3.x) >= 0.0 ? data[0] : r1.y));
        r3 = -abs(r2.x) >= 0.0 ? data[4] : (-abs(r3.w) >= 0.0 ? data[3] : r4);
        r3 = -abs(r2.z) >= 0.0 ? data[6] : (-abs(r2.y) >= 0.0 ? data[5] : r3);
        r2 = (-abs(r2.w) >= 0.0 ? data[7] : r3) * texcoord0 + r0;
        r0 = r1.z >= 0.0 ? r2 : r0;
        r1.x = r1.w;
    }
    oC0 = r0;
    return oC0;
}
