// ps_3_0 shader decompiled by ps30
float4 radius : register(c1); // the table's type: int
float2 step_uv : register(c0);
sampler2D s0_ : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.zw = 0.0;
    r1 = 0.0;
    r2.x = 0.0;
    r2.y = -radius.x;
    for (int n0 = 0; n0 < int4(255, 0, 0, 0).x; n0++) {
        if (radius.x < r2.y) break;
        r0.xy = step_uv * r2.y + texcoord0.xy;
        r3 = tex2Dlod(s0_, r0);
        r1 = r1 + r3;
        r2.xy = r2.xy + 1.0;
    }
    oC0 = (1.0 / r2.x) * r1;
    return oC0;
}
