// ps_3_0 shader decompiled by ps30
float lodFade : register(c0);
sampler2D albedoMap : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float2 vpos : VPOS) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = frac((dot(vpos, float2(0.25, 0.125)) + 0.0)) * 0.125;
    r0.yz = frac((0.5 * vpos));
    r0.x = dot(r0.yz, float2(0.5, 0.25)) + r0.x;
    r0.y = lodFade + 1.0;
    r0.z = lodFade >= 0.0 ? lodFade : r0.y;
    r0.y = r0.y - r0.x;
    r0.z = 1.0 - r0.z;
    r0.x = r0.x - r0.z;
    r0 = lodFade >= 0.0 ? r0.x : r0.y;
    clip(r0);
    oC0 = tex2D(albedoMap, texcoord0.xy);
    return oC0;
}
