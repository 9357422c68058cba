// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xy = (-abs(texcoord0.xy) >= 0.0 ? 1.0 : 0.0) + abs(texcoord0.xy);
    r1.xz = log2(abs(r0.x));
    r1.yw = log2(abs(r0.y));
    r0 = frac(-r1.zwzw) + r1;
    r1.xz = 1.0 / exp2(r0.z);
    r2.x = exp2(r0.w);
    r1.yw = 1.0 / r2.x;
    oC0 = texcoord0.xyxy * r1 + (r0 * 0.125);
    return oC0;
}
