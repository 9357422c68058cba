// oracle: target=ps_2_0
// ps_1_4 shader decompiled by ps30 (HLSL for ps_2_0)
// ps_1_x rules as arithmetic: constants clamped to [-1, 1] once, colour inputs to [0, 1],
// every result to [-8.0, 8.0] (PixelShader1xMaxValue 8.0), r0 saturated as the pixel's colour
// c12 + n: stage n's bump-environment matrix (D3DTSS_BUMPENVMAT00, 01, 10, 11)
float4 c15 : register(c15);
sampler2D s2 : register(s2);
sampler2D s4 : register(s4);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r16 = 0, r24 = 0;
    r16 = float4(1.0, 0.5, 0.25, 0.0);
    r2 = clamp(tex2D(s2, texcoord0.xy), -8.0, 8.0);
    r3.xyz = clamp(texcoord1.xyz, -8.0, 8.0);
    r0 = clamp(r16, -8.0, 8.0);
    r1 = float4(-1.0, 0.0, 0.5, 1.0);
    r24.xy = (r2.y * c15.zw + (r2.x * c15.xy + r16.xy)) * 0.5;
    r3.xy = clamp(r24.xy, -8.0, 8.0);
    r4 = clamp(tex2D(s4, r3.xy), -8.0, 8.0);
    r24 = clamp(r16, -8.0, 8.0) + r4;
    oC0 = saturate(clamp(r24, -8.0, 8.0));
    return oC0;
}
