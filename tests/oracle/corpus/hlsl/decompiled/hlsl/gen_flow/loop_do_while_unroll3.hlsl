// ps_3_0 shader decompiled by ps30
float4 k : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0 = (texcoord0 * k + texcoord1) * k + texcoord1;
    oC0 = (r0 * k + texcoord1) * k + texcoord1;
    return oC0;
}
