// ps_3_0 shader decompiled by ps30
float4 w[6] : register(c0);

float4 main(float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0 = 0.0;
    r1.x = 0.0;
    for (int n0 = 0; n0 < int4(255, 0, 0, 0).x; n0++) {
        r1.y = 6.0;
        if (r1.x >= r1.y) break;
        r2 = r1.x + float4(-0.0, -1.0, -2.0, -3.0);
        r1.yzw = r1.x + float3(-4.0, -5.0, 1.0);
        r3.y = 0.0;
        r2.x = -abs(r2.x) >= 0.0 ? w[0].w : r3.y;
        r2.x = -abs(r2.y) >= 0.0 ? w[1].w : r2.x;
        r2.x = -abs(r2.z) >= 0.0 ? w[2].w : r2.x;
        r1.y = -abs(r1.y) >= 0.0 ? w[4].w : (-abs(r2.w) >= 0.0 ? w[3].w : r2.x);
        r1.y = (-abs(r1.z) >= 0.0 ? w[5].w : r1.y) - texcoord1.w;
        r1.z = r1.y >= 0.0 ? r1.x : r1.w;
        r2 = r1.z + float4(-2.0, -3.0, -4.0, -5.0);
        r3.xz = r1.z + float2(-0.0, -1.0);
        r4 = -abs(r3.x) >= 0.0 ? w[0] : r3.y;
        r3 = -abs(r2.x) >= 0.0 ? w[2] : (-abs(r3.z) >= 0.0 ? w[1] : r4);
        r3 = -abs(r2.z) >= 0.0 ? w[4] : (-abs(r2.y) >= 0.0 ? w[3] : r3);
        r2 = r0 + (-abs(r2.w) >= 0.0 ? w[5] : r3);
        r0 = r1.y >= 0.0 ? r2 : r0;
        r1.x = r1.w;
    }
    oC0 = r0;
    return oC0;
}
