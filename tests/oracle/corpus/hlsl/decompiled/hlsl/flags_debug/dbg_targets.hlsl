// ps_3_0 shader decompiled by ps30
float4x4 xf : register(c0);

void main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1, out precise float4 oC2 : COLOR2, out precise float4 oC3 : COLOR3, out precise float oDepth : DEPTH)
{
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    oC0 = 0;
    oC1 = 0;
    oC2 = 0;
    oC3 = 0;
    oDepth = 0;
    r0.w = dot(texcoord0, xf._m00_m10_m20_m30);
    r0.z = dot(texcoord0, xf._m01_m11_m21_m31);
    r0.y = dot(texcoord0, xf._m02_m12_m22_m32);
    r0.x = dot(texcoord0, xf._m03_m13_m23_m33);
    r4 = r0.wzyx;
    r1.x = dot(texcoord1.xyz, texcoord1.xyz);
    r1.y = dot(texcoord1.xyz, texcoord1.yzx);
    r1.z = dot(texcoord1.xyz, texcoord1.zxy);
    r1.w = 0.0;
    r0 = r0;
    r2.xyz = texcoord1.xyz;
    r2.w = r0.w;
    oC0 = r4;
    oC1 = r1;
    oC2 = r0;
    oC3 = r2;
    oDepth = (r0.y * (1.0 / r0.x));
}
