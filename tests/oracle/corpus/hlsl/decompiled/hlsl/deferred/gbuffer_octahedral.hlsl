// ps_3_0 shader decompiled by ps30
float metalness : register(c1);
float roughnessValue : register(c0);
sampler2D albedoMap : register(s0);

void main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1)
{
    precise float4 r0 = 0, r1 = 0;
    oC0 = 0;
    oC1 = 0;
    r0.xyz = normalize(texcoord1.xyz);
    r0.w = abs(r0.y) + abs(r0.x);
    r0.w = 1.0 / (abs(r0.z) + r0.w);
    r0.xyz = r0.w * r0.xyz;
    r1.xy = 1.0 - abs(r0.yx);
    r1.zw = r0.xy >= 0.0 ? 1.0 : -1.0;
    oC1.xy = (r0.z >= 0.0 ? r0.xy : (r1.zw * r1.xy)) * 0.5 + 0.5;
    oC0.xyz = tex2D(albedoMap, texcoord0.xy).xyz;
    oC0.w = metalness;
    r0.xw = float2(1.0, 0.0);
    oC1.zw = roughnessValue * r0.xw + r0.wx;
}
