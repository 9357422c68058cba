// ps_3_0 shader decompiled by ps30
float4x4 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    oC0.x = dot(texcoord0, M._m00_m10_m20_m30);
    oC0.y = dot(texcoord0, M._m01_m11_m21_m31);
    oC0.z = dot(texcoord0, M._m02_m12_m22_m32);
    oC0.w = dot(texcoord0, M._m03_m13_m23_m33);
    return oC0;
}
