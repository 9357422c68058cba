// ps_3_0 shader decompiled by ps30
float4 lights[8] : register(c0);
int4 count : register(i0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 color0 : COLOR0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0.xyz = 0.0;
    r1.x = 0.0;
    for (int n0 = 0; n0 < count.x; n0++) {
        r2 = r1.x + float4(-0.0, -1.0, -2.0, -3.0);
        r3 = r1.x + float4(-4.0, -5.0, -6.0, -7.0);
        r4 = -abs(r2.x) >= 0.0 ? lights[0] : 0.0;
        r4 = -abs(r2.z) >= 0.0 ? lights[2] : (-abs(r2.y) >= 0.0 ? lights[1] : r4);
        r2 = -abs(r2.w) >= 0.0 ? lights[3] : r4;
        r2 = -abs(r3.y) >= 0.0 ? lights[5] : (-abs(r3.x) >= 0.0 ? lights[4] : r2);
        r2 = -abs(r3.w) >= 0.0 ? lights[7] : (-abs(r3.z) >= 0.0 ? lights[6] : r2);
        r1.y = saturate(dot(texcoord0.xyz, r2.xyz));
        r0.xyz = r1.y * r2.w + r0.xyz;
        r1.x = r1.x + 1.0;
    }
    r0.w = 1.0;
    oC0 = r0 * color0;
    return oC0;
}
