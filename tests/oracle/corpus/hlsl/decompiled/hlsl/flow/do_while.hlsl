// ps_3_0 shader decompiled by ps30
float4 seed : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.x = 1.618;
    r1 = frac((texcoord0 * r0.x + seed));
    r2 = r1;
    for (int n0 = 0; n0 < int4(9, 0, 0, 0).x; n0++) {
        if (0.1 >= r2.x) break;
        r3 = r2 * r0.x + seed;
        r2 = frac(r3);
    }
    oC0.xyz = r2.xyz;
    oC0.w = r2.w;
    return oC0;
}
