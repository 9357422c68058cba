// ps_3_0 shader decompiled by ps30
float AOStrength : register(c2);
float3 GroundColor : register(c1);
float3 SkyColor : register(c0);
sampler2D AlbedoTexture : register(s0);
sampler2D OcclusionTexture : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = rsqrt(abs(dot(texcoord1.xyz, texcoord1.xyz)));
    r0.x = (r0.x * texcoord1.y) * 0.5 + 0.5;
    r0.yzw = SkyColor - GroundColor;
    r0.xyz = (r0.x * r0.yzw + GroundColor) * tex2D(AlbedoTexture, texcoord0.xy).xyz;
    r0.w = tex2D(OcclusionTexture, texcoord0.xy).x - 1.0;
    r0.w = AOStrength * r0.w + 1.0;
    oC0.xyz = r0.w * r0.xyz;
    oC0.w = 1.0;
    return oC0;
}
