// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.x = log2(abs(((-abs(texcoord0.x) >= 0.0 ? 1.0 : 0.0) + abs(texcoord0.x))));
    r0.y = frac(-r0.x);
    r0.x = r0.y + r0.x;
    r0.y = exp2(r0.x);
    r0.x = r0.x * 0.125;
    r0.y = 1.0 / r0.y;
    oC0 = texcoord0.x * r0.y + r0.x;
    return oC0;
}
