// ps_3_0 shader decompiled by ps30
float4 w[6] : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0 = 0.0;
    r1.x = 0.0;
    for (int n0 = 0; n0 < int4(6, 0, 0, 0).x; n0++) {
        r2 = r1.x + float4(-2.0, -3.0, -4.0, -5.0);
        r1.xyz = r1.x + float3(1.0, -0.0, -1.0);
        r3 = -abs(r1.y) >= 0.0 ? w[0] : 0.0;
        r3 = -abs(r2.x) >= 0.0 ? w[2] : (-abs(r1.z) >= 0.0 ? w[1] : r3);
        r3 = -abs(r2.z) >= 0.0 ? w[4] : (-abs(r2.y) >= 0.0 ? w[3] : r3);
        r2 = -abs(r2.w) >= 0.0 ? w[5] : r3;
        r0 = r2 * texcoord0 + r0;
    }
    oC0 = r0;
    return oC0;
}
