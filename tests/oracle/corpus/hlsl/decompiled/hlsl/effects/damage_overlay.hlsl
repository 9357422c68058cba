// ps_3_0 shader decompiled by ps30
float damage : register(c0);
float pulse : register(c1);
sampler2D sceneS : register(s0);
sampler2D splatS : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xy = texcoord0.xy - 0.5;
    r0.x = rsqrt(abs((dot(r0.xy, r0.xy) + 0.0)));
    r0.x = (1.0 / r0.x) - 0.3;
    r0.x = saturate(r0.x + r0.x);
    r0.y = r0.x * -2.0 + 3.0;
    r0.x = r0.x * r0.x;
    r0.x = r0.x * r0.y;
    r1.xy = float2(0.4, 0.6);
    r0.y = pulse * r1.x + r1.y;
    r0.x = r0.y * r0.x;
    r0.y = tex2D(splatS, texcoord0.xy).w * damage;
    r0.x = saturate(r0.x * damage + r0.y);
    r0.y = 0.6 * damage;
    r1 = tex2D(sceneS, texcoord0.xy);
    r0.z = dot(r1.xyz, float3(0.333, 0.333, 0.333));
    r2.xyz = lerp(r1.xyz, r0.z, r0.y);
    r0.yzw = float3(0.6, 0.0, 0.0) - r2.xyz;
    oC0.xyz = r0.x * r0.yzw + r2.xyz;
    oC0.w = 1.0;
    return oC0;
}
