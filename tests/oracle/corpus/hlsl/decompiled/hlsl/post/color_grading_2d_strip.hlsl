// ps_3_0 shader decompiled by ps30
sampler2D src : register(s0);
sampler2D lutStrip : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0 = saturate(tex2D(src, texcoord0.xy));
    r1.x = r0.z * 15.0;
    r1.y = frac(r1.x);
    r1.x = r1.x - r1.y;
    r1.yz = r1.x + float2(1.0, -14.0);
    r1.y = r1.y * 0.0625;
    r2.z = r1.z >= 0.0 ? 0.9375 : r1.y;
    r2.yw = 0.0;
    r0.xy = r0.xy * 15.0 + 0.5;
    r3 = tex2D(lutStrip, (r0.xy * float2(0.00390625, 0.0625) + r2.zw));
    r2.x = r1.x * 0.0625;
    r0.z = r0.z * 15.0 - r1.x;
    oC0.w = r0.w;
    r1 = tex2D(lutStrip, (r0.xy * float2(0.00390625, 0.0625) + r2.xy));
    r0.xyw = r3.xyz - r1.xyz;
    oC0.xyz = r0.z * r0.xyw + r1.xyz;
    return oC0;
}
