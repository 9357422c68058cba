// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = rsqrt(abs((dot(texcoord0.xy, texcoord0.xy) + 0.0))) * texcoord0.xyxy;
    return oC0;
}
