// ps_3_0 shader decompiled by ps30
float3 eye : register(c1);
float4 fogTint : register(c2);
float4 sphere : register(c0);
sampler2D depthTexture : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = eye - sphere.xyz;
    r0.w = sphere.w * -sphere.w + dot(r0.xyz, r0.xyz);
    r0.x = dot(r0.xyz, normalize((texcoord1.xyz - eye)));
    r1 = r0.x * r0.x - r0.w;
    r0.y = 1.0 / rsqrt(abs(r1.w));
    clip(r1);
    r0.z = r0.y - r0.x;
    r0.x = -r0.y - r0.x;
    r0.x = r0.x >= 0.0 ? -r0.x : -0.0;
    r2.x = min(tex2Dproj(depthTexture, texcoord0).x, r0.z);
    r1.x = max((r0.x + r2.x), 0.0);
    r0.x = (1.0 / (sphere.w + sphere.w)) * r1.x;
    oC0.w = (r0.x * r0.x) * fogTint.w;
    oC0.xyz = fogTint.xyz;
    return oC0;
}
