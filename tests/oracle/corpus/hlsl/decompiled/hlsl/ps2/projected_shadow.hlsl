// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
float depthBias : register(c0);
float mipBias : register(c1);
sampler2D shadowMap : register(s0);
sampler2D cookie : register(s1);
sampler2D albedo : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r1 = tex2Dproj(cookie, texcoord1);
    r1.w = texcoord0.z * (1.0 / texcoord0.w) - depthBias;
    r1.w = (tex2Dproj(shadowMap, texcoord0).x - r1.w) >= 0.0 ? 1.0 : 0.3;
    r0.xy = texcoord2.xy;
    r0.z = 0.0;
    r0.w = mipBias;
    r0 = tex2Dbias(albedo, r0);
    r1.xyz = r1.xyz * r0.xyz;
    r0.xyz = r1.w * r1.xyz;
    oC0 = r0;
    return oC0;
}
