// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = -dot(texcoord0, texcoord0) >= 0.0 ? 0.25 : 1.0;
    return oC0;
}
