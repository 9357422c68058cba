// ps_3_0 shader decompiled by ps30
float dissolveAmount : register(c0);
float3 edgeColor : register(c2);
float edgeWidth : register(c1);
sampler2D albedo : register(s0);
sampler2D noiseMap : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(noiseMap, texcoord0.xy).x - dissolveAmount;
    clip(r0);
    r0.x = 1.0 / edgeWidth;
    r0.x = saturate(r0.x * r0.w);
    r0.y = r0.x * -2.0 + 3.0;
    r0.x = r0.x * r0.x;
    r0.x = r0.y * -r0.x + 1.0;
    r1 = tex2D(albedo, texcoord0.xy);
    r0.yzw = edgeColor - r1.xyz;
    oC0.xyz = r0.x * r0.yzw + r1.xyz;
    oC0.w = r1.w;
    return oC0;
}
