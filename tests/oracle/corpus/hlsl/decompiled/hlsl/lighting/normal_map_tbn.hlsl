// ps_3_0 shader decompiled by ps30
float4 Ambient : register(c2);
float4 SunColor : register(c1);
float3 SunDirection : register(c0);
sampler2D ColorSampler : register(s0);
sampler2D NormalSampler : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, float4 texcoord3 : TEXCOORD3) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r2.xyz = tex2D(NormalSampler, texcoord0.xy).xyz * 2.0 - 1.0;
    r0.xyz = r2.x * normalize(texcoord1.xyz) + (normalize(texcoord2.xyz) * r2.y);
    r0.xyz = r2.z * normalize(texcoord3.xyz) + r0.xyz;
    r0.x = saturate(dot(normalize(r0.xyz), SunDirection));
    r0 = SunColor * r0.x + Ambient;
    oC0 = r0 * tex2D(ColorSampler, texcoord0.xy);
    return oC0;
}
