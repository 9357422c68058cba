// oracle: target=ps_2_0
// ps_1_3 shader decompiled by ps30 (HLSL for ps_2_0)
// ps_1_x rules as arithmetic: constants clamped to [-1, 1] once, colour inputs to [0, 1],
// every result to [-8.0, 8.0] (PixelShader1xMaxValue 8.0), r0 saturated as the pixel's colour
sampler2D s0 : register(s0);

void main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, out precise float4 oC0 : COLOR0, out precise float oDepth : DEPTH)
{
    precise float4 r0 = 0, r1 = 0, r8 = 0, r12 = 0, r29 = 0;
    oC0 = 0;
    oDepth = 0;
    r8 = clamp(tex2D(s0, texcoord0.xy), -8.0, 8.0);
    r12.x = dot(texcoord1.xyz, r8.xyz);
    r12.y = dot(texcoord2.xyz, r8.xyz);
    r29.x = r12.x * (1.0 / r12.y);
    oDepth = saturate((-abs(r12.y) >= 0.0 ? 1.0 : r29.x));
    r0 = float4(1.0, 0.5, 0.25, 0.0);
    r1 = float4(-1.0, 0.0, 0.5, 1.0);
    oC0 = saturate(r0);
}
