// ps_3_0 shader decompiled by ps30
float4 FogColor : register(c1);
float3 LightDir : register(c0);
sampler2D BaseMap : register(s0);
sampler2D NormalMap : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = saturate(dot(normalize((tex2D(NormalMap, texcoord0.xy).xyz * 2.0 - 1.0)), LightDir));
    r1 = tex2D(BaseMap, texcoord0.xy);
    oC0.w = r1.w;
    oC0.xyz = texcoord2.x * (r1.xyz * r0.x - FogColor.xyz) + FogColor.xyz;
    return oC0;
}
