// oracle: target=ps_2_0
// ps_1_4 shader decompiled by ps30 (HLSL for ps_2_0)
// ps_1_x rules as arithmetic: constants clamped to [-1, 1] once, colour inputs to [0, 1],
// every result to [-8.0, 8.0] (PixelShader1xMaxValue 8.0), r0 saturated as the pixel's colour
float4 c0 : register(c0);
float4 c1 : register(c1);
sampler2D s0 : register(s0);
sampler2D s5 : register(s5);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, float4 texcoord3 : TEXCOORD3) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0, r25 = 0;
    r0 = clamp(tex2D(s0, texcoord0.xy), -8.0, 8.0);
    r1.xyz = clamp(texcoord1.xyz, -8.0, 8.0);
    r2.xyz = clamp(texcoord2.xyz, -8.0, 8.0);
    r3.xyz = saturate(dot((r0 * 2.0 - 1.0).xyz, (r1 * 2.0 - 1.0).xyz).xxx);
    r4.xyz = saturate(dot((r0 * 2.0 - 1.0).xyz, (r2 * 2.0 - 1.0).xyz).xxx);
    r5 = clamp(tex2D(s5, texcoord3.xy), -8.0, 8.0);
    r25.w = (r4.z * r4.z) * 4.0;
    r4.w = clamp(r25.w, -8.0, 8.0);
    r3.xyz = clamp((r3.xyz * clamp(c0, -1.0, 1.0).xyz), -8.0, 8.0);
    r4.xyz = clamp((r5.xyz * clamp(c1, -1.0, 1.0).xyz), -8.0, 8.0);
    r0.w = clamp(r5.w, -8.0, 8.0);
    r0.xyz = saturate((r4.xyz * r4.w + r3.xyz));
    r0.xyz = clamp(((0.5 - r0.w).xxx >= 0.0 ? (1.0 - r0).xyz : r0.xyz), -8.0, 8.0);
    oC0 = saturate(r0);
    return oC0;
}
