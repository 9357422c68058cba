// ps_3_0 shader decompiled by ps30
float3 eyeW : register(c4);
float t : register(c3);
float4 waves[3] : register(c0);
samplerCUBE sky : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.z = 0.0;
    r0.x = dot(waves[1].xy, waves[1].xy) + r0.z;
    r0.xy = rsqrt(abs(r0.x)) * waves[1].xy;
    r0.w = (1.0 / waves[1].w) * 6.2831855;
    r1.x = 1.0 / r0.w;
    r1.y = r1.x * 9.8;
    r1.x = r0.w * (r1.x * waves[1].z);
    r1.y = 1.0 / rsqrt(abs(r1.y));
    r1.y = dot(r0.xy, texcoord0.xz) + -(r1.y * t);
    r0.w = (r0.w * r1.y);
    r2.xy = float2(cos(r0.w), sin(r0.w));
    r0.w = r1.x * r2.x;
    r0.xy = r0.w * r0.xy;
    r0.w = dot(waves[0].xy, waves[0].xy) + r0.z;
    r1.xy = rsqrt(abs(r0.w)) * waves[0].xy;
    r0.w = (1.0 / waves[0].w) * 6.2831855;
    r1.z = 1.0 / r0.w;
    r1.w = r1.z * 9.8;
    r1.z = r0.w * (r1.z * waves[0].z);
    r1.w = rsqrt(abs(r1.w));
    r1.w = (1.0 / r1.w) * t;
    r0.w = (r0.w * (dot(r1.xy, texcoord0.xz) + -r1.w));
    r3.xy = float2(cos(r0.w), sin(r0.w));
    r0.w = r1.z * r3.x;
    r1.z = waves[1].z * -r2.y + (waves[0].z * -r3.y + 1.0);
    r0.xy = r1.xy * -r0.w - r0.xy;
    r0.z = dot(waves[2].xy, waves[2].xy) + r0.z;
    r0.zw = rsqrt(abs(r0.z)) * waves[2].xy;
    r1.x = (1.0 / waves[2].w) * 6.2831855;
    r1.y = 1.0 / r1.x;
    r1.w = r1.y * 9.8;
    r1.y = r1.y * waves[2].z;
    r1.y = r1.y * r1.x;
    r1.w = 1.0 / rsqrt(abs(r1.w));
    r1.w = dot(r0.zw, texcoord0.xz) + -(r1.w * t);
    r1.x = (r1.w * r1.x);
    r2.xy = float2(cos(r1.x), sin(r1.x));
    r1.x = r1.y * r2.x;
    r2.y = waves[2].z * -r2.y + r1.z;
    r2.xz = r0.zw * -r1.x + r0.xy;
    r0.xyz = normalize(r2.xyz);
    r2.xyz = normalize((texcoord0.xyz - eyeW));
    r0.w = dot(r2.xyz, r0.xyz);
    r0.w = r0.w + r0.w;
    oC0 = texCUBE(sky, (r0.xyz * -r0.w + r2.xyz));
    return oC0;
}
