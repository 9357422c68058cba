// ps_3_0 shader decompiled by ps30
float4 fallback : register(c0);
sampler2D maskS : register(s0);
sampler2D expensive : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0 = tex2D(maskS, texcoord0.xy);
    r0.y = 0.5 - r0.x;
    if (0.5 < r0.x) {
        r1 = float4(1.0, 1.0, 0.0, 0.0) * texcoord0.xyxx;
        r2 = tex2Dlod(expensive, r1) + tex2Dlod(expensive, (r1 + float4(0.01, 0.01, 0.0, 1.0)));
        r3 = tex2Dlod(expensive, (r1 + float4(0.02, 0.02, 0.0, 2.0)));
        r2 = r2 + r3;
        r1 = tex2Dlod(expensive, (r1 + float4(0.03, 0.03, 0.0, 3.0)));
        r1 = (r1 + r2) * 0.25;
    } else {
        r1 = 0.0;
    }
    oC0 = r0.y >= 0.0 ? fallback : r1;
    return oC0;
}
