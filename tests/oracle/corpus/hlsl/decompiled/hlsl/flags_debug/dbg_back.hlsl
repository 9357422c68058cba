// ps_3_0 shader decompiled by ps30
float4 k : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = k * texcoord0;
    r1 = r0 + k;
    r0 = r0 * r1;
    r1 = r1 + r0;
    r0 = r0 * r1;
    r1 = r1 + r0;
    oC0 = (r0 * r1);
    return oC0;
}
