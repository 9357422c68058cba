// ps_3_0 shader decompiled by ps30
float3x4 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0;
    r0.xyz = M._m00_m10_m20 * texcoord0.x + (M._m01_m11_m21 * texcoord0.y);
    oC0.xyz = M._m03_m13_m23 * texcoord0.w + (M._m02_m12_m22 * texcoord0.z + r0.xyz);
    oC0.w = 0.0;
    return oC0;
}
