// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0 = texcoord0;
    r1.xy = float2(cos(r0.x), sin(r0.x));
    r2.x = r1.y;
    r3.xy = float2(cos(r0.y), sin(r0.y));
    r1.y = r3.x;
    r2.y = r3.y;
    r3.xy = float2(cos(r0.z), sin(r0.z));
    r4.xy = float2(cos(r0.w), sin(r0.w));
    r1.z = r3.x;
    r2.z = r3.y;
    r1.w = r4.x;
    r2.w = r4.y;
    oC0 = r2 * texcoord1 + (r1 * texcoord2);
    return oC0;
}
