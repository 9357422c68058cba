// oracle: target=ps_2_0
// ps_1_4 shader decompiled by ps30 (HLSL for ps_2_0)
// ps_1_x rules as arithmetic: constants clamped to [-1, 1] once, colour inputs to [0, 1],
// every result to [-8.0, 8.0] (PixelShader1xMaxValue 8.0), r0 saturated as the pixel's colour
sampler2D s2 : register(s2);
sampler2D s3 : register(s3);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r16 = 0, r17 = 0, r24 = 0;
    r16 = float4(1.0, 0.5, 0.25, 0.0);
    r17 = float4(-1.0, 0.0, 0.5, 1.0);
    r2 = clamp(tex2D(s2, texcoord0.xy), -8.0, 8.0);
    r0 = clamp(r16, -8.0, 8.0);
    r24 = max(r17, -8.0);
    r1 = min(r24, 8.0);
    [loop] for (int n0 = 0; n0 < 6; n0++) {
        r24 = max((r0 + r16), -8.0);
        r0 = min(r24, 8.0);
    }
    r3 = clamp(tex2D(s3, texcoord1.xy), -8.0, 8.0);
    r24 = r16;
    [loop] for (int n0 = 0; n0 < 5; n0++) {
        r0 = clamp(r24, -8.0, 8.0);
        r24 = r0 + r16;
    }
    oC0 = saturate(clamp(r24, -8.0, 8.0));
    return oC0;
}
