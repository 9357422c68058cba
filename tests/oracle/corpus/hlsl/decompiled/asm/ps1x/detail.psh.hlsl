// oracle: target=ps_2_0
// ps_1_1 shader decompiled by ps30 (HLSL for ps_2_0)
// ps_1_x rules as arithmetic: constants clamped to [-1, 1] once, colour inputs to [0, 1],
// every result to [-8.0, 8.0] (PixelShader1xMaxValue 8.0), r0 saturated as the pixel's colour
float4 c0 : register(c0);
float4 c1 : register(c1);
sampler2D s0 : register(s0);
sampler2D s1 : register(s1);

float4 main(float4 color0 : COLOR0, float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r8 = 0, r9 = 0, r16 = 0, r24 = 0;
    color0 = saturate(color0);
    r16 = clamp(c0, -1.0, 1.0);
    r8 = clamp(tex2D(s0, texcoord0.xy), -8.0, 8.0);
    r9 = clamp(tex2D(s1, texcoord1.xy), -8.0, 8.0);
    r0.w = clamp((r8.w * color0.w), -8.0, 8.0);
    r24.xyz = (r8.xyz * color0.xyz) * 2.0;
    r0.xyz = clamp(r24.xyz, -8.0, 8.0);
    r1.w = clamp(r16.w, -8.0, 8.0);
    r1.xyz = clamp(((r9 * 2.0 - 1.0).xyz * r16.xyz + r0.xyz), -8.0, 8.0);
    r0.xyz = clamp((r1.w * r1.xyz + (1.0 - r1.w) * clamp(c1, -1.0, 1.0).xyz), -8.0, 8.0);
    oC0 = saturate(r0);
    return oC0;
}
