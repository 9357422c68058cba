// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
float4 ambient : register(c1);
float detailScale : register(c0);
sampler2D baseMap : register(s0);
sampler2D lightMap : register(s1);
sampler2D detailMap : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 color0 : COLOR0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = tex2D(detailMap, (texcoord0.xy * detailScale));
    r2 = tex2D(baseMap, texcoord0.xy);
    r0.xyz = r0.xyz + r0.xyz;
    r1.xyz = (tex2D(lightMap, texcoord1.xy).xyz * 2.0 + ambient.xyz) * r2.xyz;
    r2.w = r2.w * color0.w;
    r2.xyz = (r0.xyz * r1.xyz) * color0.xyz;
    oC0 = r2;
    return oC0;
}
