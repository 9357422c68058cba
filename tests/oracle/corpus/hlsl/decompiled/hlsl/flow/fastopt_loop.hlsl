// ps_3_0 shader decompiled by ps30
float4 dirs[4] : register(c0);
sampler2D src : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0.zw = 0.0;
    r1 = 0.0;
    r2.x = 0.0;
    for (int n0 = 0; n0 < int4(255, 0, 0, 0).x; n0++) {
        r2.y = 4.0;
        if (r2.x >= r2.y) break;
        r3 = r2.x + float4(-0.0, -1.0, -2.0, -3.0);
        r4.x = 0.0;
        r2.yz = -abs(r3.y) >= 0.0 ? dirs[1].xy : (-abs(r3.x) >= 0.0 ? dirs[0].xy : r4.x);
        r2.yz = -abs(r3.w) >= 0.0 ? dirs[3].xy : (-abs(r3.z) >= 0.0 ? dirs[2].xy : r2.yz);
        r3 = r1;
        r2.w = 1.0;
        for (int n1 = 0; n1 < int4(3, 0, 0, 0).x; n1++) {
            r0.xy = r2.yz * r2.w + texcoord0.xy;
            r4 = tex2Dlod(src, r0);
            r3 = r3 + r4;
            r2.w = r2.w + 1.0;
        }
        r1 = r3;
        r2.x = r2.x + 1.0;
    }
    oC0 = r1 * 0.083333336;
    return oC0;
}
