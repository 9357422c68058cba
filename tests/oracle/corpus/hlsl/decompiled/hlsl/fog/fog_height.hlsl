// ps_3_0 shader decompiled by ps30
float3 cameraPosition : register(c0);
float fogGlobalDensity : register(c2);
float fogHeightFalloff : register(c1);
float3 fogInscatter : register(c3);
float3 sunDir : register(c4);
float3 sunFogColor : register(c5);
sampler2D sceneColor : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.x = (-cameraPosition.y * fogHeightFalloff) * 1.442695;
    r0.x = exp2(r0.x) * fogGlobalDensity;
    r0.yzw = texcoord1.xyz - cameraPosition;
    r1.x = rsqrt(abs(dot(r0.yzw, r0.yzw)));
    r2.xyz = r0.yzw * r1.x;
    r0.y = 1.0 / (r0.z * r1.x + 1.0e-5);
    r0.z = -(1.0 / r1.x) * r2.y;
    r1.x = max(dot(r2.xyz, sunDir), 0.0);
    r0.w = r1.x * r1.x;
    r0.w = r0.w * r0.w;
    r0.z = (r0.z * fogHeightFalloff) * 1.442695;
    r0.z = 1.0 - exp2(r0.z);
    r0.xw = r0.zw * r0.xw;
    r0.x = saturate(r0.y * r0.x);
    r0.yzw = r0.w * (sunFogColor - fogInscatter) + fogInscatter;
    r1 = tex2D(sceneColor, texcoord0.xy);
    r0.yzw = r0.yzw - r1.xyz;
    oC0.xyz = r0.x * r0.yzw + r1.xyz;
    oC0.w = 1.0;
    return oC0;
}
