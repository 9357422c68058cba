// ps_3_0 shader decompiled by ps30
float2 nearFar : register(c1);
float softness : register(c0);
sampler2D particleTex : register(s0);
sampler2D sceneDepth : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 color0 : COLOR0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = (1.0 / texcoord1.w) * texcoord1.z;
    r0.y = nearFar.y - nearFar.x;
    r0.x = 1.0 / (r0.x * -r0.y + nearFar.y);
    r0.z = nearFar.y * nearFar.x;
    r0.x = r0.x * r0.z;
    r0.y = 1.0 / (tex2Dproj(sceneDepth, texcoord1).x * -r0.y + nearFar.y);
    r0.x = r0.z * r0.y - r0.x;
    r0.y = 1.0 / softness;
    r1 = tex2D(particleTex, texcoord0.xy) * color0;
    oC0.w = saturate(r0.y * r0.x) * r1.w;
    oC0.xyz = r1.xyz;
    return oC0;
}
