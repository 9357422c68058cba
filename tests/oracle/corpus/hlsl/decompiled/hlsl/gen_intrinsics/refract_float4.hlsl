// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = texcoord2.x * texcoord2.x;
    r0.y = dot(texcoord0, texcoord1);
    r0.z = r0.y * -r0.y + 1.0;
    r0.x = r0.x * -r0.z + 1.0;
    r0.z = r0.x >= 0.0 ? 1.0 : 0.0;
    r0.x = r0.z * r0.x;
    r0.z = r0.z * texcoord2.x;
    r0.x = 1.0 / rsqrt(abs(r0.x));
    oC0 = r0.z * texcoord0 - ((r0.z * r0.y + r0.x) * texcoord1);
    return oC0;
}
