// ps_3_0 shader decompiled by ps30
float4 a : register(c0);
float4 b : register(c1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = (a.wzyx * texcoord0.wzyx) + b.wzyx;
    r0 = r0 * r0;
    oC0 = (r0 + (-texcoord0.wzyx));
    return oC0;
}
