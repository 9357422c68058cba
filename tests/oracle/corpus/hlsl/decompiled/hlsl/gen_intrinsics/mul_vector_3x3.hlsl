// ps_3_0 shader decompiled by ps30
float3x3 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    oC0.x = dot(texcoord0.xyz, M._m00_m10_m20);
    oC0.y = dot(texcoord0.xyz, M._m01_m11_m21);
    oC0.z = dot(texcoord0.xyz, M._m02_m12_m22);
    oC0.w = 1.0;
    return oC0;
}
