// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.x = texcoord0.x;
    r0.y = texcoord1.x - r0.x;
    oC0 = texcoord2.x * r0.y + r0.x;
    return oC0;
}
