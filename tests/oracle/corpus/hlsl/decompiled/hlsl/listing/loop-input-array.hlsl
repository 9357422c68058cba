// ps_3_0 shader decompiled by ps30
float4 arr[6] : register(c0);

float4 main(float4 texcoord[4] : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0 = 0.0;
    r1.x = 0.0;
    for (int i = 0; i < 4; i++) {
        r2 = r1.x + float4(0.0, -1.0, -2.0, -3.0);
        r1.y = 0.0;
        r3 = -abs(r2.z) >= 0.0 ? arr[4] : (-abs(r2.y) >= 0.0 ? arr[3] : (-abs(r2.x) >= 0.0 ? arr[2] : r1.y));
        r2 = -abs(r2.w) >= 0.0 ? arr[5] : r3;
        r0 = r2 * abs(texcoord[i].x) + r0;
        r1.x = r1.x + 1.0;
    }
    oC0 = r0;
    return oC0;
}
