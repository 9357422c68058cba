// ps_3_0 shader decompiled by ps30
float4 w[6] : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0 = w[0] * texcoord0 + (w[1] * texcoord0);
    r0 = w[3] * texcoord0 + (w[2] * texcoord0 + r0);
    oC0 = w[5] * texcoord0 + (w[4] * texcoord0 + r0);
    return oC0;
}
