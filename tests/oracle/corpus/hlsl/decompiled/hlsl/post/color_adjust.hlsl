// ps_3_0 shader decompiled by ps30
float Brightness : register(c0);
float Contrast : register(c1);
float3 Gain : register(c6);
float3 Gamma : register(c5);
float3 Lift : register(c4);
float Saturation : register(c2);
float3 Tint : register(c3);
sampler2D Screen : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = tex2D(Screen, texcoord0.xy).xyz - 0.5;
    r0.xyz = (r0.xyz * Contrast + Brightness) + 0.5;
    r0.w = dot(r0.xyz, float3(0.299, 0.587, 0.114));
    r1.xyz = lerp(r0.w, r0.xyz, Saturation);
    r0.xyz = r1.xyz * Tint;
    r0.xyz = Lift * (r1.xyz * -Tint + 1.0) + r0.xyz;
    r1.xyz = max((r0.xyz * Gain), 0.0);
    r0.x = log2(abs(r1.x));
    r0.y = log2(abs(r1.y));
    r0.z = log2(abs(r1.z));
    r1.x = 1.0 / Gamma.x;
    r1.y = 1.0 / Gamma.y;
    r1.z = 1.0 / Gamma.z;
    r0.xyz = r0.xyz * r1.xyz;
    oC0.x = exp2(r0.x);
    oC0.y = exp2(r0.y);
    oC0.z = exp2(r0.z);
    oC0.w = 1.0;
    return oC0;
}
