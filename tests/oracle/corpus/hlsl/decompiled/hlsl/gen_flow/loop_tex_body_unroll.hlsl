// ps_3_0 shader decompiled by ps30
float2 d : register(c0);
sampler2D s : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = tex2D(s, (d + texcoord0.xy)) + tex2D(s, texcoord0.xy);
    r1.xy = d;
    r0 = r0 + tex2D(s, (r1.xy * 2.0 + texcoord0.xy));
    r1 = r1.xyxy * float4(3.0, 3.0, 4.0, 4.0) + texcoord0.xyxy;
    r2 = tex2D(s, r1.xy);
    oC0 = tex2D(s, r1.zw) + (r0 + r2);
    return oC0;
}
