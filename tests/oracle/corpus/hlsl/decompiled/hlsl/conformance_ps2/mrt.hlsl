// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30

void main(float4 texcoord0 : TEXCOORD0, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1, out precise float4 oC2 : COLOR2, out precise float4 oC3 : COLOR3)
{
    precise float4 r0 = 0;
    oC0 = 0;
    oC1 = 0;
    oC2 = 0;
    oC3 = 0;
    oC0 = texcoord0;
    oC1 = (texcoord0 * 0.5);
    oC3 = (texcoord0 + 0.25);
    oC2 = texcoord0.wzyx;
}
