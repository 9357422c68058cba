// ps_3_0 shader decompiled by ps30
float4x4 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0;
    r0 = M._m00_m10_m20_m30 * texcoord0.x + (M._m01_m11_m21_m31 * texcoord0.y);
    oC0 = M._m03_m13_m23_m33 * texcoord0.w + (M._m02_m12_m22_m32 * texcoord0.z + r0);
    return oC0;
}
