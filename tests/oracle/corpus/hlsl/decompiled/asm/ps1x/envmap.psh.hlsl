// oracle: target=ps_2_0
// ps_1_3 shader decompiled by ps30 (HLSL for ps_2_0)
// ps_1_x rules as arithmetic: constants clamped to [-1, 1] once, colour inputs to [0, 1],
// every result to [-8.0, 8.0] (PixelShader1xMaxValue 8.0), r0 saturated as the pixel's colour
float4 c2 : register(c2);
sampler2D s0 : register(s0);
sampler2D s3 : register(s3);

float4 main(float4 color0 : COLOR0, float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, float4 texcoord3 : TEXCOORD3) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r8 = 0, r11 = 0, r12 = 0, r18 = 0, r24 = 0;
    color0 = saturate(color0);
    r18 = clamp(c2, -1.0, 1.0);
    r8 = clamp(tex2D(s0, texcoord0.xy), -8.0, 8.0);
    r12.x = dot(texcoord1.xyz, (r8 * 2.0 - 1.0).xyz);
    r12.y = dot(texcoord2.xyz, (r8 * 2.0 - 1.0).xyz);
    r12.z = dot(texcoord3.xyz, (r8 * 2.0 - 1.0).xyz);
    r11 = clamp(tex2D(s3, r12.xy), -8.0, 8.0);
    r24.xyz = clamp((r18.xyz * r11.xyz + (1.0 - r18.xyz) * color0.xyz), -8.0, 8.0) * r8.w;
    r0.w = clamp((r18.w - -color0.w), -8.0, 8.0);
    r0.xyz = saturate(r24.xyz);
    oC0 = saturate(r0);
    return oC0;
}
