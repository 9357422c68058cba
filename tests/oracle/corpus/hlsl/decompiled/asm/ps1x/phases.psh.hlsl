// oracle: target=ps_2_0
// ps_1_4 shader decompiled by ps30 (HLSL for ps_2_0)
// ps_1_x rules as arithmetic: constants clamped to [-1, 1] once, colour inputs to [0, 1],
// every result to [-8.0, 8.0] (PixelShader1xMaxValue 8.0), r0 saturated as the pixel's colour
// c12 + n: stage n's bump-environment matrix (D3DTSS_BUMPENVMAT00, 01, 10, 11)
float4 c14 : register(c14);
sampler2D s1 : register(s1);
sampler2D s2 : register(s2);
sampler2D s3 : register(s3);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r16 = 0, r24 = 0;
    r16 = float4(0.25, 0.0, 0.0, 0.25);
    r1 = clamp(tex2D(s1, texcoord0.xy), -8.0, 8.0);
    r2.xyz = clamp(texcoord1.xyz, -8.0, 8.0);
    r24.xy = r1.y * c14.zw + (r1.x * c14.xy + r16.xy);
    r2.xy = clamp(r24.xy, -8.0, 8.0);
    r2 = clamp(tex2D(s2, r2.xy), -8.0, 8.0);
    r3 = clamp(tex2D(s3, texcoord2.xy), -8.0, 8.0);
    r0.w = clamp(r16.z, -8.0, 8.0);
    r24.xyz = (r2.xyz * (r3 * 2.0 - 1.0).xyz) * 2.0;
    r0.xyz = clamp(r24.xyz, -8.0, 8.0);
    oC0 = saturate(r0);
    return oC0;
}
