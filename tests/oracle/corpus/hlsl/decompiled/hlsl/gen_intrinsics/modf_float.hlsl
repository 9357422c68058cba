// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.x = frac(texcoord0.x);
    r0.y = -r0.x >= 0.0 ? 0.0 : 1.0;
    r0.x = texcoord0.x - r0.x;
    r0.y = texcoord0.x >= 0.0 ? 0.0 : r0.y;
    r0.x = r0.y + r0.x;
    r0.y = texcoord0.x - r0.x;
    oC0 = r0.x * 0.5 + r0.y;
    return oC0;
}
