// ps_3_0 shader decompiled by ps30
float4x4 ViewProj : register(c4);
float4x4 World : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.y = dot(texcoord0, World._m01_m11_m21_m31);
    r1 = r0.y * ViewProj._m01_m11_m21_m31;
    r0.x = dot(texcoord0, World._m00_m10_m20_m30);
    r1 = ViewProj._m00_m10_m20_m30 * r0.x + r1;
    r0.z = dot(texcoord0, World._m02_m12_m22_m32);
    r1 = ViewProj._m02_m12_m22_m32 * r0.z + r1;
    r0.w = dot(texcoord0, World._m03_m13_m23_m33);
    oC0 = r0 * 0.5 + (ViewProj._m03_m13_m23_m33 * r0.w + r1);
    return oC0;
}
