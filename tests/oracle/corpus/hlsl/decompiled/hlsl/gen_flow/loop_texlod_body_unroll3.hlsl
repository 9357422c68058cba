// ps_3_0 shader decompiled by ps30
float2 d : register(c0);
sampler2D s : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xy = d + texcoord0.xy;
    r0.zw = 0.0;
    r0 = tex2Dlod(s, r0) + tex2Dlod(s, (float4(1.0, 1.0, 0.0, 0.0) * texcoord0.xyxx));
    r1.xy = d * 2.0 + texcoord0.xy;
    r1.zw = 0.0;
    oC0 = r0 + tex2Dlod(s, r1);
    return oC0;
}
