// ps_3_0 shader decompiled by ps30
float emissive : register(c2);
float flowSpeed : register(c1);
float time : register(c0);
sampler2D flowMap : register(s0);
sampler2D lavaTex : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.zw = float2(0.5, 1.0);
    r0.x = time;
    r0.y = frac((r0.x * flowSpeed + r0.z));
    r1.xy = tex2D(flowMap, texcoord0.xy).xy * 2.0 - 1.0;
    r2 = tex2D(lavaTex, (r1.xy * r0.y + texcoord0.xy));
    r0.x = frac((r0.x * flowSpeed));
    r0.y = 0.5 - r0.x;
    r1 = tex2D(lavaTex, (r1.xy * r0.x + texcoord0.xy));
    r3 = lerp(r1, r2, abs((r0.y + r0.y)));
    oC0 = (emissive * r3.w + r0.w) * r3;
    return oC0;
}
