// ps_3_0 shader decompiled by ps30
float4x4 matCM : register(c4);
row_major float4x4 matRM : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0;
    r0 = texcoord0.z * matRM[2] + (texcoord0.x * matRM[0] + (matRM[1] * texcoord0.y));
    r0 = (texcoord0.w * matRM[3] + r0) + mul(texcoord0, matCM);
    r1.x = dot(matRM[0], texcoord0);
    r1.y = dot(matRM[1], texcoord0);
    r1.z = dot(matRM[2], texcoord0);
    r1.w = dot(matRM[3], texcoord0);
    r0 = r0 + r1;
    r1 = matCM._m02_m12_m22_m32 * texcoord0.z + (matCM._m00_m10_m20_m30 * texcoord0.x + (matCM._m01_m11_m21_m31 * texcoord0.y));
    oC0 = r0 + (matCM._m03_m13_m23_m33 * texcoord0.w + r1);
    return oC0;
}
