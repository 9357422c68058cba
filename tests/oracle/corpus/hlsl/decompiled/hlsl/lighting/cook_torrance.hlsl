// ps_3_0 shader decompiled by ps30
float F0 : register(c4);
float3 cameraPos : register(c2);
float3 lightDirection : register(c0);
float3 lightRadiance : register(c1);
float roughness : register(c3);
sampler2D albedoTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = cameraPos - texcoord1.xyz;
    r0.w = rsqrt(abs(dot(r0.xyz, r0.xyz)));
    r1.xyz = r0.xyz * r0.w + lightDirection;
    r0.xyz = r0.w * r0.xyz;
    r2.xyz = normalize(r1.xyz);
    r0.w = saturate(dot(r0.xyz, r2.xyz));
    r1.x = 1.0 - r0.w;
    r0.w = 1.0 / r0.w;
    r1.y = r1.x * r1.x;
    r1.y = r1.y * r1.y;
    r1.x = r1.y * r1.x;
    r1.y = 1.0;
    r2.w = lerp(F0, r1.y, r1.x);
    r1.xyz = normalize(texcoord2.xyz);
    r1.w = saturate(dot(r1.xyz, r2.xyz));
    r2.x = r1.w * r1.w - 1.0;
    r2.y = r1.w * r1.w;
    r1.w = r1.w + r1.w;
    r2.z = roughness * roughness;
    r2.z = r2.y * r2.z;
    r2.y = r2.y * r2.z;
    r2.z = 1.0 / r2.z;
    r2.x = r2.z * r2.x;
    r2.x = exp2((r2.x * 1.442695));
    r2.y = 1.0 / (r2.y * 3.1415927);
    r2.x = r2.y * r2.x;
    r2.x = r2.w * r2.x;
    r0.x = saturate(dot(r1.xyz, r0.xyz));
    r0.y = saturate(dot(r1.xyz, lightDirection));
    r0.x = r0.x + 0.0001;
    r0.z = r0.x * r1.w;
    r0.x = 1.0 / (r0.x * 4.0);
    r1.x = r0.w * (r0.y * r1.w);
    r2.y = min(r1.x, (r0.w * r0.z));
    r0.z = min(r2.y, 1.0) * r2.x;
    r0.x = r0.x * r0.z;
    r0.xzw = (tex2D(albedoTex, texcoord0.xy).xyz * 0.31830987 + r0.x) * lightRadiance;
    oC0.xyz = r0.y * r0.xzw;
    oC0.w = 1.0;
    return oC0;
}
