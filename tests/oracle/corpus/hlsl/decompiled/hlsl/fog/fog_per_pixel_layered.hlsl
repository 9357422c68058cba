// ps_3_0 shader decompiled by ps30
float3 camFwd : register(c4);
float3 camRight : register(c2);
float3 camUp : register(c3);
float3 fogCol : register(c1);
float4 fogParams : register(c0);
sampler2D sceneRT : register(s0);
sampler2D depthRT : register(s1);
sampler2D noiseTex : register(s2);
samplerCUBE skyCube : register(s3);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xy = texcoord0.xy * fogParams.z + (fogParams.w * float2(0.01, 0.003));
    r0.x = tex2D(noiseTex, r0.xy).x * 0.4 + 0.8;
    r1 = tex2D(depthRT, texcoord0.xy);
    r0.y = r1.x - fogParams.x;
    r0.z = 0.999 - r1.x;
    r0.y = saturate(r0.y * fogParams.y);
    r0.x = r0.x * r0.y;
    r1.xyz = (texcoord0.x * 2.0 - 1.0) * camRight + camFwd;
    r1.xyz = (texcoord0.y * -2.0 + 1.0) * camUp + r1.xyz;
    r0.yzw = r0.z >= 0.0 ? fogCol : texCUBE(skyCube, r1.xyz).xyz;
    r1 = tex2D(sceneRT, texcoord0.xy);
    r0.yzw = r0.yzw - r1.xyz;
    oC0.xyz = r0.x * r0.yzw + r1.xyz;
    oC0.w = 1.0;
    return oC0;
}
