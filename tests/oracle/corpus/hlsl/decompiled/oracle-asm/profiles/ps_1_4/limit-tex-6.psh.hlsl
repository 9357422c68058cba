// oracle: target=ps_2_0
// ps_1_4 shader decompiled by ps30 (HLSL for ps_2_0)
// ps_1_x rules as arithmetic: constants clamped to [-1, 1] once, colour inputs to [0, 1],
// every result to [-8.0, 8.0] (PixelShader1xMaxValue 8.0), r0 saturated as the pixel's colour
sampler2D s0 : register(s0);
sampler2D s1 : register(s1);
sampler2D s2 : register(s2);
sampler2D s3 : register(s3);
sampler2D s4 : register(s4);
sampler2D s5 : register(s5);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, float4 texcoord3 : TEXCOORD3, float4 texcoord4 : TEXCOORD4, float4 texcoord5 : TEXCOORD5) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    r0 = clamp(tex2D(s0, texcoord0.xy), -8.0, 8.0);
    r1 = clamp(tex2D(s1, texcoord1.xy), -8.0, 8.0);
    r2 = clamp(tex2D(s2, texcoord2.xy), -8.0, 8.0);
    r3 = clamp(tex2D(s3, texcoord3.xy), -8.0, 8.0);
    r4 = clamp(tex2D(s4, texcoord4.xy), -8.0, 8.0);
    r5 = clamp(tex2D(s5, texcoord5.xy), -8.0, 8.0);
    r0 = float4(1.0, 0.5, 0.25, 0.0);
    r1 = float4(-1.0, 0.0, 0.5, 1.0);
    oC0 = saturate(r0);
    return oC0;
}
