// ps_3_0 shader decompiled by ps30
float4 deepColor : register(c1);
float depthFade : register(c2);
float foamEdge : register(c3);
float4 shallowColor : register(c0);
float time : register(c4);
sampler2D sceneDepth : register(s0);
sampler2D foamTex : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = 0.05 * time;
    r0 = tex2D(foamTex, (texcoord0.xy * 4.0 + r0.x));
    r0.y = 1.0 / foamEdge;
    r0.z = tex2Dproj(sceneDepth, texcoord1).x - texcoord2.x;
    r0.y = 1.0 - saturate(r0.y * r0.z);
    r0.w = 1.0 - r0.y;
    r0.x = r0.x - r0.w;
    r0.x = r0.x >= 0.0 ? r0.y : 0.0;
    r0.y = 1.0 / depthFade;
    oC0.w = saturate(r0.z * 4.0);
    r0.yzw = saturate(r0.y * r0.z) * (deepColor.xyz - shallowColor.xyz) + shallowColor.xyz;
    oC0.xyz = r0.x + r0.yzw;
    return oC0;
}
