// ps_3_0 shader decompiled by ps30
float EnvStrength : register(c0);
sampler2D SphereMap : register(s0);
sampler2D BaseTexture : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xyz = normalize(texcoord2.xyz);
    r1.xyz = normalize(texcoord1.xyz);
    r0.w = dot(r0.xyz, r1.xyz);
    r0.w = r0.w + r0.w;
    r0.xyz = r1.xyz * -r0.w + r0.xyz;
    r0.z = r0.z + 1.0;
    r0.z = r0.z * r0.z;
    r0.z = dot(r0.xy, r0.xy) + r0.z;
    r0.z = 1.0 / rsqrt(abs(r0.z));
    r0.z = 1.0 / (r0.z + r0.z);
    r0 = tex2D(SphereMap, (r0.xy * r0.z + 0.5));
    r1 = tex2D(BaseTexture, texcoord0.xy);
    oC0 = (r0 * EnvStrength) * r1.w + r1;
    return oC0;
}
