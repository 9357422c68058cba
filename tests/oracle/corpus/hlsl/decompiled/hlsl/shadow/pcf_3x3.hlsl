// ps_3_0 shader decompiled by ps30
float DepthBias : register(c1);
float3 LightDir : register(c2);
float ShadowMapSize : register(c0);
sampler2D Diffuse : register(s0);
sampler2D ShadowMap : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0.x = 1.0 / texcoord1.w;
    r0.yz = (r0.x * texcoord1.xy) * float2(0.5, -0.5) + 0.5;
    r0.x = texcoord1.z * r0.x - DepthBias;
    r0.w = 1.0 / ShadowMapSize;
    r1.x = 0.0;
    r2.y = -1.0;
    for (int n0 = 0; n0 < int4(3, 0, 0, 0).x; n0++) {
        r3.x = r1.x;
        r3.y = -1.0;
        for (int n1 = 0; n1 < int4(3, 0, 0, 0).x; n1++) {
            r2.x = r3.y;
            r1.yz = r2.xy * r0.w + r0.yz;
            r4 = tex2D(ShadowMap, r1.yz);
            r1.y = (r4.x - r0.x) >= 0.0 ? 1.0 : 0.0;
            r3.x = r1.y + r3.x;
            r3.y = r3.y + 1.0;
        }
        r1.x = r3.x;
        r2.y = r2.y + 1.0;
    }
    r0.x = r1.x * 0.11111111;
    r0.y = saturate(dot(normalize(texcoord2.xyz), LightDir));
    r0.x = r0.y * r0.x;
    oC0 = (r0.x * 0.7 + 0.3) * tex2D(Diffuse, texcoord0.xy);
    return oC0;
}
