// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xy = texcoord0.xy;
    r1.xy = float2(cos(r0.x), sin(r0.x));
    r2.xy = float2(cos(r0.y), sin(r0.y));
    r0.xz = r1.x;
    r1.xz = r1.y;
    r0.yw = r2.x;
    r1.yw = r2.y;
    oC0 = r1 * texcoord1.xyxy + (r0 * texcoord2.xyxy);
    return oC0;
}
