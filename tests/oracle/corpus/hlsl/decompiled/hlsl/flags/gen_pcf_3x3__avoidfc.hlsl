// ps_3_0 shader decompiled by ps30
float DepthBias : register(c1);
float3 LightDir : register(c2);
float ShadowMapSize : register(c0);
sampler2D Diffuse : register(s0);
sampler2D ShadowMap : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.x = 1.0 / texcoord1.w;
    r0.yz = r0.x * texcoord1.xy;
    r0.x = texcoord1.z * r0.x - DepthBias;
    r0.yz = r0.yz * float2(0.5, -0.5) + 0.5;
    r0.w = 1.0 / ShadowMapSize;
    r1.x = -r0.x + tex2D(ShadowMap, (r0.yz - r0.w)).x;
    r2 = r0.w * float4(0.0, -1.0, 1.0, -1.0) + r0.yzyz;
    r3 = tex2D(ShadowMap, r2.xy);
    r1.y = -r0.x + tex2D(ShadowMap, r2.zw).x;
    r1.z = r3.x - r0.x;
    r1.xyz = r1.xyz >= 0.0 ? 1.0 : 0.0;
    r1.x = r1.z + r1.x;
    r1.x = r1.y + r1.x;
    r2 = r0.w * float4(-1.0, 0.0, -1.0, 1.0) + r0.yzyz;
    r3 = tex2D(ShadowMap, r2.xy);
    r1.y = -r0.x + tex2D(ShadowMap, r2.zw).x;
    r1.z = r3.x - r0.x;
    r1.yz = r1.yz >= 0.0 ? 1.0 : 0.0;
    r1.x = r1.z + r1.x;
    r1.z = (-r0.x + tex2D(ShadowMap, r0.yz).x) >= 0.0 ? 1.0 : 0.0;
    r2 = r0.w * float4(1.0, 0.0, 0.0, 1.0) + r0.yzyz;
    r0.y = -r0.x + tex2D(ShadowMap, (r0.w + r0.yz)).x;
    r3 = tex2D(ShadowMap, r2.xy);
    r0.z = -r0.x + tex2D(ShadowMap, r2.zw).x;
    r0.x = r3.x - r0.x;
    r0.xyz = r0.xyz >= 0.0 ? 1.0 : 0.0;
    r0.x = r1.y + (r0.x + (r1.z + r1.x));
    r0.x = r0.z + r0.x;
    r0.x = (r0.y + r0.x) * 0.11111111;
    r0.y = saturate(dot(normalize(texcoord2.xyz), LightDir));
    r0.x = r0.y * r0.x;
    oC0 = (r0.x * 0.7 + 0.3) * tex2D(Diffuse, texcoord0.xy);
    return oC0;
}
