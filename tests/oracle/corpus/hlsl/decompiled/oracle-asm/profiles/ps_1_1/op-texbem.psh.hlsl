// oracle: target=ps_2_0
// ps_1_1 shader decompiled by ps30 (HLSL for ps_2_0)
// ps_1_x rules as arithmetic: constants clamped to [-1, 1] once, colour inputs to [0, 1],
// every result to [-8.0, 8.0] (PixelShader1xMaxValue 8.0), r0 saturated as the pixel's colour
// c12 + n: stage n's bump-environment matrix (D3DTSS_BUMPENVMAT00, 01, 10, 11)
float4 c13 : register(c13);
sampler2D s0 : register(s0);
sampler2D s1 : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r8 = 0, r9 = 0, r24 = 0, r29 = 0;
    r8 = clamp(tex2D(s0, texcoord0.xy), -8.0, 8.0);
    r29.xy = r8.x * c13.xy + texcoord1.xy;
    r9 = clamp(tex2D(s1, (r8.y * c13.zw + r29.xy)), -8.0, 8.0);
    r0 = float4(1.0, 0.5, 0.25, 0.0);
    r1 = float4(-1.0, 0.0, 0.5, 1.0);
    r24 = r0 + r9;
    oC0 = saturate(clamp(r24, -8.0, 8.0));
    return oC0;
}
