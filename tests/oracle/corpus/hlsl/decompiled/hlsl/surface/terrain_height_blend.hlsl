// ps_3_0 shader decompiled by ps30
float blendDepth : register(c0);
sampler2D rockTex : register(s0);
sampler2D grassTex : register(s1);
sampler2D maskTex : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = tex2D(maskTex, texcoord1.xy);
    r1 = tex2D(rockTex, texcoord0.xy);
    r0.y = (r1.w - r0.x) + 1.0;
    r2 = tex2D(grassTex, texcoord0.xy);
    r0.x = r0.x + r2.w;
    r0.z = max(r0.y, r0.x) - blendDepth;
    r0.xy = r0.xy - r0.z;
    r1.w = max(r0.y, 0.0);
    r2.w = max(r0.x, 0.0);
    r0.xyz = r2.w * r2.xyz;
    r0.w = r1.w + r2.w;
    r0.xyz = r1.xyz * r1.w + r0.xyz;
    r0.w = 1.0 / r0.w;
    oC0.xyz = r0.w * r0.xyz;
    oC0.w = 1.0;
    return oC0;
}
