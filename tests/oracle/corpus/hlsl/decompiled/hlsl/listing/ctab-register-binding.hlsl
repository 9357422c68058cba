// ps_3_0 shader decompiled by ps30
float4 c : register(c5);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = c * texcoord0.x + 0.95;
    return oC0;
}
