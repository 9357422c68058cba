// ps_3_0 shader decompiled by ps30
float4 k : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.xy = k.zw * texcoord1.yx;
    r0.zw = r0.xy + texcoord0.xy;
    r0.xy = r0.xy;
    oC0.xy = r0.zw;
    oC0.zw = r0.xy;
    return oC0;
}
