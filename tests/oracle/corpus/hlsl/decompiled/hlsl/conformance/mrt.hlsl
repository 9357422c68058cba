// ps_3_0 shader decompiled by ps30

void main(float4 texcoord0 : TEXCOORD0, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1, out precise float4 oC2 : COLOR2)
{
    oC0 = 0;
    oC1 = 0;
    oC2 = 0;
    oC1 = 0.5 * texcoord0;
    oC0 = texcoord0;
    oC2 = texcoord0.wzyx;
}
