// ps_3_0 shader decompiled by ps30
float4x4 projectorViewProj : register(c0);
sampler2D projTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0;
    r0.x = dot(texcoord0, projectorViewProj._m00_m10_m20_m30);
    r0.y = dot(texcoord0, projectorViewProj._m01_m11_m21_m31);
    r0.z = dot(texcoord0, projectorViewProj._m02_m12_m22_m32);
    r0.w = dot(texcoord0, projectorViewProj._m03_m13_m23_m33);
    r1 = r0 * float4(0.5, -0.5, 1.0, 1.0) + (r0.w * float4(0.5, 0.5, 0.0, 0.0));
    oC0 = -r0.w >= 0.0 ? 0.0 : tex2Dproj(projTex, r1);
    return oC0;
}
