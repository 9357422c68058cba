// ps_3_0 shader decompiled by ps30
float heading : register(c1);
float2 playerUV : register(c0);
float zoom : register(c2);
sampler2D mapTex : register(s0);
sampler2D iconTex : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.xy = texcoord0.xy * 2.0 - 1.0;
    r1 = dot(r0.xy, -r0.xy) + 1.0;
    clip(r1);
    r1.xy = float2(0.15915494, 0.5);
    r0.z = frac((heading * r1.x + r1.y)) * 6.2831855 - 3.1415927;
    r1.xy = float2(cos(r0.z), sin(r0.z));
    r0.z = r0.y * r1.y;
    r2.x = r0.x * r1.x - r0.z;
    r2.y = dot(r0.xy, r1.yx) + 0.0;
    r1 = tex2D(mapTex, (r2.xy * zoom + playerUV));
    r0.zw = abs(r0.xy) - 0.125;
    r0.x = dot(r0.xy, r0.xy) + 0.0;
    r0.x = 1.0 / rsqrt(abs(r0.x));
    r0.x = saturate((r0.x - 0.9) * 9.999998);
    r0.yz = r0.zw >= 0.0 ? 0.0 : 1.0;
    r0.y = r0.z * r0.y;
    r2 = tex2D(iconTex, (texcoord0.xy * 8.0 - 3.5));
    r3.xyz = lerp(r1.xyz, r2.xyz, (r0.y * r2.w));
    r0.y = r0.x * -2.0 + 3.0;
    r0.x = r0.x * r0.x;
    oC0.xyz = (r0.x * r0.y) * -r3.xyz + r3.xyz;
    oC0.w = 1.0;
    return oC0;
}
