// ps_3_0 shader decompiled by ps30
float intensity : register(c1);
float4 tintColor : register(c0);
sampler2D baseMap : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = saturate(rsqrt(abs(dot(texcoord1.xyz, texcoord1.xyz))) * texcoord1.z);
    r1 = tex2D(baseMap, texcoord0.xy) * tintColor;
    oC0.xyz = (r0.x * intensity) * r1.xyz;
    oC0.w = r1.w;
    return oC0;
}
