// ps_3_0 shader decompiled by ps30
float cutoff : register(c3);
float3 sunCol : register(c1);
float3 sunDir : register(c0);
float translucency : register(c2);
sampler2D leafTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float vface : VFACE) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(leafTex, texcoord0.xy);
    r1 = r0.w - cutoff;
    r0.xyz = r0.xyz * sunCol;
    clip(r1);
    r1.xyz = (-(vface >= 0.0 ? 1.0 : -1.0) >= 0.0 ? -1.0 : 1.0) * normalize(texcoord1.xyz);
    r0.w = saturate(dot(r1.xyz, sunDir));
    r0.w = (saturate(dot(-r1.xyz, sunDir)) * translucency + r0.w) + 0.2;
    oC0.xyz = r0.w * r0.xyz;
    oC0.w = 1.0;
    return oC0;
}
