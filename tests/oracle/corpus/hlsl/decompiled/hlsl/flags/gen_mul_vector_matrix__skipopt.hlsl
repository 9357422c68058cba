// ps_3_0 shader decompiled by ps30
float4x4 ViewProj : register(c4);
float4x4 World : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = mul(texcoord0, World);
    r1 = (r0.x * ViewProj._m00_m10_m20_m30) + (r0.y * ViewProj._m01_m11_m21_m31);
    r1 = r1 + (r0.z * ViewProj._m02_m12_m22_m32);
    r2 = r0.w * ViewProj._m03_m13_m23_m33;
    oC0 = (r1 + r2) + (r0 * 0.5);
    return oC0;
}
