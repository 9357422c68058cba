// ps_3_0 shader decompiled by ps30
float4x3 M : register(c4);
float3x4 N : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0 = M._m01_m11_m21_m31;
    r2 = M._m00_m10_m20_m30;
    r1 = r2 * N._m00 + (r0 * N._m10);
    r3 = M._m02_m12_m22_m32;
    oC0.x = dot(texcoord0, (r3 * N._m20 + r1));
    r1 = r2 * N._m01 + (r0 * N._m11);
    oC0.y = dot(texcoord0, (r3 * N._m21 + r1));
    r1 = r2 * N._m02 + (r0 * N._m12);
    oC0.z = dot(texcoord0, (r3 * N._m22 + r1));
    r0 = r2 * N._m03 + (r0 * N._m13);
    oC0.w = dot(texcoord0, (r3 * N._m23 + r0));
    return oC0;
}
