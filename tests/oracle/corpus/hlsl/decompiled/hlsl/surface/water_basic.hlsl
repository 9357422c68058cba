// ps_3_0 shader decompiled by ps30
float3 CameraPos : register(c6);
float Distortion : register(c3);
float3 SunDirection : register(c5);
float Time : register(c0);
float3 WaterTint : register(c4);
float2 WaveDir0 : register(c1);
float2 WaveDir1 : register(c2);
sampler2D WaveNormals : register(s0);
sampler2D ReflectionRT : register(s1);
sampler2D RefractionRT : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    r0.x = Time;
    r0.yzw = tex2D(WaveNormals, (WaveDir0 * r0.x + texcoord0.xy)).xzy * 2.0 - 1.0;
    r1.xy = texcoord0.xy * 1.7 + (r0.x * WaveDir1);
    r0.xyz = tex2D(WaveNormals, r1.xy).xzy * 2.0 + r0.yzw;
    r1.xyz = normalize((r0.xyz - 1.0));
    r0.xy = ((1.0 / texcoord1.w) * texcoord1.xy) * float2(0.5, -0.5) + 0.5;
    r0.zw = r1.xz * Distortion + r0.xy;
    r2 = tex2D(RefractionRT, (r1.xz * -Distortion + r0.xy));
    r0.xyz = r2.xyz * -WaterTint + tex2D(ReflectionRT, r0.zw).xyz;
    r3.xyz = CameraPos - texcoord2.xyz;
    r0.w = rsqrt(abs(dot(r3.xyz, r3.xyz)));
    r4.xyz = r0.w * r3.xyz;
    r0.w = saturate(dot(r1.xyz, normalize((r3.xyz * r0.w + SunDirection))));
    r1.x = 1.0 - saturate(dot(r4.xyz, r1.xyz));
    r1.y = pow(abs(r0.w), 256.0);
    r0.w = r1.x * r1.x;
    r0.w = r0.w * r0.w;
    r0.w = (r0.w * r1.x) * 0.98 + 0.02;
    oC0.xyz = r1.y * 4.0 + (r0.w * r0.xyz + (r2.xyz * WaterTint));
    oC0.w = 1.0;
    return oC0;
}
