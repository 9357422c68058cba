// ps_3_0 shader decompiled by ps30
float gain : register(c0);
float2 noiseOffset : register(c1);
sampler2D screen : register(s0);
sampler2D noise : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xy = (texcoord0.xy - 0.5) * float2(1.6, 1.0);
    r0.x = dot(r0.xy, r0.xy) + 0.0;
    r0.x = 1.0 / rsqrt(abs(r0.x));
    r0.x = saturate((r0.x - 0.4) * 10.000001);
    r0.y = r0.x * -2.0 + 3.0;
    r0.x = r0.x * r0.x;
    r0.x = r0.y * -r0.x + 1.0;
    r0.y = tex2D(noise, (texcoord0.xy * 3.0 + noiseOffset)).x * 0.2;
    r0.z = dot(tex2D(screen, texcoord0.xy).xyz, float3(0.3, 0.59, 0.11));
    r0.y = r0.z * gain + r0.y;
    oC0.xyz = (r0.y * r0.x) * float3(0.1, 0.95, 0.2);
    oC0.w = 1.0;
    return oC0;
}
