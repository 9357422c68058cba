// ps_3_0 shader decompiled by ps30
float3 AmbientColor : register(c2);
float3 LightColor : register(c1);
float3 LightDir : register(c0);
sampler2D DiffuseMap : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 color0 : COLOR0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xyz = LightColor * saturate(dot(normalize(texcoord1.xyz), LightDir)) + AmbientColor;
    r1 = tex2D(DiffuseMap, texcoord0.xy) * color0;
    oC0.xyz = r0.xyz * r1.xyz;
    oC0.w = r1.w;
    return oC0;
}
