// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = texcoord0;
    r1 = texcoord2 - r0;
    r0 = texcoord1 - r0;
    r2.x = 1.0 / r0.x;
    r2.y = 1.0 / r0.y;
    r2.z = 1.0 / r0.z;
    r2.w = 1.0 / r0.w;
    r0 = saturate(r1 * r2);
    r1 = r0 * -2.0 + 3.0;
    oC0 = (r0 * r0) * r1;
    return oC0;
}
