// ps_3_0 shader decompiled by ps30
float3x3 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    r0.xyz = M._m01_m11_m21;
    r1.xyz = r0.zxy * M._m12_m22_m02;
    r0.x = dot((r0.yzx * M._m22_m02_m12 - r1.xyz), M._m00_m10_m20);
    r0.y = 1.0 / r0.x;
    oC0.w = r0.x;
    r1.x = M._m11;
    r1.y = M._m12;
    r1.z = M._m10;
    r2.x = M._m22;
    r2.y = M._m20;
    r2.z = M._m21;
    r0.xzw = r1.yxz * r2.yxz - ((r1.yzx * r2.zxy).yxz);
    r3.x = r0.z;
    r4.x = M._m02;
    r4.y = M._m00;
    r4.z = M._m01;
    r2.xyz = r2.zyx * r4.xzy - ((r2.xyz * r4.zxy).xzy);
    r3.y = r2.x;
    r1.xyz = r4.zxy * r1.yzx - (r1.xyz * r4.xyz);
    r3.z = r1.x;
    oC0.x = dot((r0.y * r3.xyz), texcoord0.xyz);
    r2.x = r0.w;
    r0.z = r2.z;
    r0.w = r1.y;
    r2.z = r1.z;
    r1.xyz = r0.y * r2.xyz;
    oC0.y = dot((r0.y * r0.xzw), texcoord0.xyz);
    oC0.z = dot(r1.xyz, texcoord0.xyz);
    return oC0;
}
