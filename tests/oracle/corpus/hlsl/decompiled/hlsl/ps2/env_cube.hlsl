// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
float4 baseColor : register(c2);
float fresnelBias : register(c0);
float fresnelScale : register(c1);
samplerCUBE envMap : register(s0);
sampler3D noise : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = normalize(texcoord0.xyz);
    r1.xyz = normalize(texcoord1.xyz);
    r0.w = dot(-r1.xyz, r0.xyz);
    r0.w = r0.w + r0.w;
    r2.xyz = r0.xyz * -r0.w - r1.xyz;
    r2.w = 1.0 - saturate(dot(r0.xyz, r1.xyz));
    r0 = texCUBE(envMap, r2.xyz);
    r1 = tex3D(noise, texcoord2.xyz);
    r0.w = r2.w * r2.w;
    r0.w = (r0.w * r0.w) * r2.w;
    r0.w = saturate(fresnelScale * r0.w + fresnelBias);
    r1.yzw = lerp(baseColor.zyx, r0.zyx, r0.w);
    r0.xyz = (r1.x * 0.25 + 0.75) * r1.wzy;
    r0.w = 1.0;
    oC0 = r0;
    return oC0;
}
