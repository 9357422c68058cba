// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = frac(texcoord0);
    r1 = -r0 >= 0.0 ? 0.0 : 1.0;
    r0 = (texcoord0 - r0) + (texcoord0 >= 0.0 ? 0.0 : r1);
    oC0 = r0 * 0.5 + (texcoord0 - r0);
    return oC0;
}
