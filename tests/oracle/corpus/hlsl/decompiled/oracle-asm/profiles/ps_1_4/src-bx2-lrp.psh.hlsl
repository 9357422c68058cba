// oracle: target=ps_2_0
// ps_1_4 shader decompiled by ps30 (HLSL for ps_2_0)
// ps_1_x rules as arithmetic: constants clamped to [-1, 1] once, colour inputs to [0, 1],
// every result to [-8.0, 8.0] (PixelShader1xMaxValue 8.0), r0 saturated as the pixel's colour

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r16 = 0, r24 = 0;
    r16 = float4(1.0, 0.5, 0.25, 0.0);
    r0 = clamp(r16, -8.0, 8.0);
    r24 = (r16 * r0 + (1.0 - r16) * (float4(-1.0, 0.0, 0.5, 1.0) * 2.0 - 1.0));
    oC0 = saturate(clamp(r24, -8.0, 8.0));
    return oC0;
}
