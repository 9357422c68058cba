// ps_3_0 shader decompiled by ps30
float4 w[4] : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r1 = w[1] * texcoord0;
    r0 = r1 * 2.0 + ((w[0] * texcoord0) * 3.0 + r1);
    r0 = (w[2] * texcoord0) * 2.0 + (w[2] * texcoord0 + r0);
    oC0 = (w[3] * texcoord0) * 2.0 + (w[3] * texcoord0 + r0);
    return oC0;
}
