// ps_3_0 shader decompiled by ps30
float3 g_EyePos : register(c2);
float4 g_LightColor : register(c1);
float3 g_LightDir : register(c0);
float g_SpecPower : register(c3);
sampler2D g_Diffuse : register(s0);
sampler2D g_Specular : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = g_EyePos - texcoord2.xyz;
    r0.w = rsqrt(abs(dot(r0.xyz, r0.xyz)));
    r1.xyz = normalize((r0.xyz * r0.w + g_LightDir));
    r0.xyz = normalize(texcoord1.xyz);
    r0.w = saturate(dot(r0.xyz, r1.xyz));
    r0.x = dot(r0.xyz, g_LightDir);
    r1 = tex2D(g_Specular, texcoord0.xy);
    r0.y = r1.w * g_SpecPower;
    r1.w = pow(abs(r0.w), r0.y);
    r0.yzw = r0.x * tex2D(g_Diffuse, texcoord0.xy).xyz;
    r0.xyz = r0.x >= 0.0 ? r0.yzw : 0.0;
    oC0.xyz = (r1.xyz * r1.w + r0.xyz) * g_LightColor.xyz;
    oC0.w = 1.0;
    return oC0;
}
