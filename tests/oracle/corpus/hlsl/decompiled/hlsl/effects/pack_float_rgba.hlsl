// ps_3_0 shader decompiled by ps30
sampler2D packedDepth : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r1.x = min(texcoord1.x, dot(tex2D(packedDepth, texcoord0.xy), float4(1.0, 0.003921569, 1.53787e-5, 6.030863e-8)));
    r0 = frac((r1.x * float4(1.0, 255.0, 65025.0, 16581375.0)));
    oC0 = r0.yzww * float4(-0.003921569, -0.003921569, -0.003921569, -0.0) + r0;
    return oC0;
}
