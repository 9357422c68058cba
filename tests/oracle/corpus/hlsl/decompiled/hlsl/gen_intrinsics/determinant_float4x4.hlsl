// ps_3_0 shader decompiled by ps30
float4x4 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = M._m02_m12_m22_m32;
    r1.x = dot((r0.zwy * M._m33_m13_m23 - (r0.wyz * M._m23_m33_m13)), M._m11_m21_m31);
    r1.y = dot((r0.wxz * M._m23_m33_m03 - (r0.zwx * M._m33_m03_m23)), M._m01_m21_m31);
    r1.z = dot((r0.ywx * M._m33_m03_m13 - (r0.wxy * M._m13_m33_m03)), M._m01_m11_m31);
    r2.xyz = r0.yzx * M._m23_m03_m13;
    r1.w = dot((r0.zxy * M._m13_m23_m03 - r2.xyz), M._m01_m11_m21);
    oC0 = dot(r1, M._m00_m10_m20_m30) * texcoord0.x;
    return oC0;
}
