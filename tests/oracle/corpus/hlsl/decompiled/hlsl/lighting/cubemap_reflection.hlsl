// ps_3_0 shader decompiled by ps30
float3 EyePosition : register(c0);
float ReflectAmount : register(c1);
sampler2D Diffuse : register(s0);
samplerCUBE EnvMap : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r1.xyz = normalize((texcoord1.xyz - EyePosition));
    r0.xyz = normalize(texcoord2.xyz);
    r0.w = dot(r1.xyz, r0.xyz);
    r0.w = r0.w + r0.w;
    r2.xyz = r0.xyz * -r0.w + r1.xyz;
    r0.x = 1.0 - saturate(dot(-r1.xyz, r0.xyz));
    r1 = texCUBE(EnvMap, r2.xyz);
    r2 = tex2D(Diffuse, texcoord0.xy);
    r0.yzw = r1.xyz - r2.xyz;
    r1.x = r0.x * r0.x;
    r0.x = r0.x * (r1.x * r1.x);
    r0.x = (r0.x * 0.95 + 0.05) * ReflectAmount;
    oC0.xyz = r0.x * r0.yzw + r2.xyz;
    oC0.w = 1.0;
    return oC0;
}
