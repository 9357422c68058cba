// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = texcoord0;
    r1.x = dot(r0, texcoord1);
    oC0 = texcoord1 * -(r1.x + r1.x) + r0;
    return oC0;
}
