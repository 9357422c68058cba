// oracle: target=ps_2_0
// ps_1_3 shader decompiled by ps30 (HLSL for ps_2_0)
// ps_1_x rules as arithmetic: constants clamped to [-1, 1] once, colour inputs to [0, 1],
// every result to [-8.0, 8.0] (PixelShader1xMaxValue 8.0), r0 saturated as the pixel's colour
sampler2D s0 : register(s0);
sampler2D s3 : register(s3);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, float4 texcoord3 : TEXCOORD3) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r8 = 0, r11 = 0, r12 = 0, r24 = 0, r27 = 0, r29 = 0;
    r8 = clamp(tex2D(s0, texcoord0.xy), -8.0, 8.0);
    r12.x = dot(texcoord1.xyz, r8.xyz);
    r12.y = dot(texcoord2.xyz, r8.xyz);
    r12.z = dot(texcoord3.xyz, r8.xyz);
    r27.x = texcoord1.w;
    r27.y = texcoord2.w;
    r27.z = texcoord3.w;
    r29.x = dot(r12.xyz, r27.xyz);
    r29.y = 1.0 / dot(r12.xyz, r12.xyz);
    r29.x = r29.x * r29.y;
    r11 = clamp(tex2D(s3, (r12.xyz * (r29.x + r29.x) - r27.xyz).xy), -8.0, 8.0);
    r0 = float4(1.0, 0.5, 0.25, 0.0);
    r1 = float4(-1.0, 0.0, 0.5, 1.0);
    r24 = r0 + r11;
    oC0 = saturate(clamp(r24, -8.0, 8.0));
    return oC0;
}
