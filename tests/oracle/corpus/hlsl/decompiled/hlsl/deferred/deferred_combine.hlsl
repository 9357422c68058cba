// ps_3_0 shader decompiled by ps30
float3 fogColour : register(c0);
float fogDensity : register(c1);
sampler2D albedoRT : register(s0);
sampler2D lightRT : register(s1);
sampler2D depthRT : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.x = (-(tex2D(depthRT, texcoord0.xy).x) * fogDensity) * 1.442695;
    r0.x = 1.0 - exp2(r0.x);
    r1 = tex2D(albedoRT, texcoord0.xy);
    r2 = tex2D(lightRT, texcoord0.xy);
    r0.yzw = r1.xyz * r2.xyz + (r1.xyz * r2.w);
    oC0.xyz = r0.x * (fogColour - r0.yzw) + r0.yzw;
    oC0.w = 1.0;
    return oC0;
}
