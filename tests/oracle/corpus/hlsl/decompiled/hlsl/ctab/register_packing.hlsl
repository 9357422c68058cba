// ps_3_0 shader decompiled by ps30
float a1 : register(c6);
float a2 : register(c7);
float a3 : register(c8);
float a4 : register(c9);
float2 b1_ : register(c10);
float2 b2_ : register(c11);
float3 c1_ : register(c12);
float4 d1 : register(c13);
float2x4 m24 : register(c0);
float4x2 m42 : register(c4);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.x = a2 * a3;
    r0 = (texcoord0 * a1 + r0.x) - a4;
    r0.xy = b1_ * b2_ + r0.xy;
    r0.xyz = r0.xyz * c1_;
    r0 = r0 + d1;
    r1.x = dot(texcoord0, m42._m00_m10_m20_m30);
    r1.y = dot(texcoord0, m42._m01_m11_m21_m31);
    r0.xy = r0.xy + r1.xy;
    r1.x = 0.0;
    r2.x = dot(texcoord0.xy, m24._m00_m10) + r1.x;
    r2.y = dot(texcoord0.xy, m24._m01_m11) + r1.x;
    r2.z = dot(texcoord0.xy, m24._m02_m12) + r1.x;
    r2.w = dot(texcoord0.xy, m24._m03_m13) + r1.x;
    oC0 = r0 + r2;
    return oC0;
}
