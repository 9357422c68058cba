// ps_3_0 shader decompiled by ps30
float4x4 M : register(c0);
float4x4 N : register(c4);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    r0 = M._m01_m11_m21_m31;
    r2 = M._m00_m10_m20_m30;
    r1 = r2 * N._m01 + (r0 * N._m11);
    r3 = M._m02_m12_m22_m32;
    r4 = M._m03_m13_m23_m33;
    r1 = r4 * N._m31 + (r3 * N._m21 + r1);
    r5 = r3 * N._m20 + (r2 * N._m00 + (r0 * N._m10));
    r1 = (r4 * N._m30 + r5) * texcoord0.x + (r1 * texcoord0.y);
    r5 = r3 * N._m22 + (r2 * N._m02 + (r0 * N._m12));
    r0 = r0 * N._m13;
    r0 = r3 * N._m23 + (r2 * N._m03 + r0);
    oC0 = (r4 * N._m33 + r0) * texcoord0.w + ((r4 * N._m32 + r5) * texcoord0.z + r1);
    return oC0;
}
