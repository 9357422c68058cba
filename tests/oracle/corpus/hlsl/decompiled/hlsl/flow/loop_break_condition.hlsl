// ps_3_0 shader decompiled by ps30
float4 params : register(c0);
sampler2D tex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0.zw = 0.0;
    r1 = 0.0;
    r2.xy = 0.0;
    for (int n0 = 0; n0 < int4(16, 0, 0, 0).x; n0++) {
        r0.xy = params.xy * r2.y + texcoord0.xy;
        r3 = tex2Dlod(tex, r0);
        r4 = r3 * (1.0 - r2.x) + r1;
        r0.x = lerp(r2.x, 1.0, r3.w);
        if (0.99 < r0.x) {
            r1 = r4;
            if (1.0 != -1.0) break;
        }
        r2.y = r2.y + 1.0;
        r1 = r4;
        r2.x = r0.x;
    }
    oC0 = r1;
    return oC0;
}
