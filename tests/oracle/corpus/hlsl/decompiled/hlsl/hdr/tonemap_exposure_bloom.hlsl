// ps_3_0 shader decompiled by ps30
float BloomIntensity : register(c0);
float KeyValue : register(c1);
float VignetteAmount : register(c2);
sampler2D Scene : register(s0);
sampler2D Bloom : register(s1);
sampler2D AdaptedLum : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = tex2D(AdaptedLum, float2(0.5, 0.5));
    r0.y = r0.x - 0.0001;
    r0.x = 1.0 / r0.x;
    r0.x = (r0.y >= 0.0 ? r0.x : 10000.0) * KeyValue;
    r0.yzw = tex2D(Bloom, texcoord0.xy).xyz * BloomIntensity + tex2D(Scene, texcoord0.xy).xyz;
    r0.xyz = (r0.x * -r0.yzw) * 1.442695;
    r1.x = exp2(r0.x);
    r1.y = exp2(r0.y);
    r1.z = exp2(r0.z);
    r0.xyz = 1.0 - r1.xyz;
    r1.xy = texcoord0.xy - 0.5;
    r0.w = dot(r1.xy, r1.xy) + 0.0;
    r0.w = r0.w * -VignetteAmount + 1.0;
    r0.xyz = saturate(r0.w * r0.xyz);
    r1.x = log2(abs(r0.x));
    r1.y = log2(abs(r0.y));
    r1.z = log2(abs(r0.z));
    r1.xyz = r1.xyz * 0.41666666;
    r2.x = exp2(r1.x);
    r2.y = exp2(r1.y);
    r2.z = exp2(r1.z);
    r1.xyz = r2.xyz * 1.055 - 0.055;
    r2.xyz = r0.xyz * 12.92;
    oC0.xyz = (0.0031308 - r0.xyz) >= 0.0 ? r2.xyz : r1.xyz;
    oC0.w = 1.0;
    return oC0;
}
