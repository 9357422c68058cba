// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = -texcoord0.x >= 0.0 ? 0.0 : 1.0;
    oC0.y = r0.x * texcoord0.x;
    r0.x = -texcoord1.x >= 0.0 ? 0.0 : r0.x;
    r0.y = pow(abs(texcoord1.x), texcoord2.x);
    oC0.z = r0.y * r0.x;
    oC0.xw = 1.0;
    return oC0;
}
