// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = 1.0 / texcoord1.x;
    r0.y = 1.0 / texcoord1.y;
    r0.z = 1.0 / texcoord1.z;
    r0.w = 1.0 / texcoord1.w;
    r0 = r0 * texcoord0;
    r1 = frac(abs(r0));
    oC0 = (r0 >= 0.0 ? r1 : -r1) * texcoord1;
    return oC0;
}
