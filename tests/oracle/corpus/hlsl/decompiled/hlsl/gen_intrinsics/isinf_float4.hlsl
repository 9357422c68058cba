// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.x = 1.0 / texcoord0.x;
    r0.y = 1.0 / texcoord0.y;
    r0.z = 1.0 / texcoord0.z;
    r0.w = 1.0 / texcoord0.w;
    oC0 = -abs(r0) >= 0.0 ? 1.0 : 0.0;
    return oC0;
}
