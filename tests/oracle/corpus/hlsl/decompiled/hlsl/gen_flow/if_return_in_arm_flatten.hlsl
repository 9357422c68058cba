// ps_3_0 shader decompiled by ps30
float4 x : register(c0);
float4 y : register(c1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    oC0 = (texcoord0.w - 0.5) >= 0.0 ? (y * texcoord0) : x;
    return oC0;
}
