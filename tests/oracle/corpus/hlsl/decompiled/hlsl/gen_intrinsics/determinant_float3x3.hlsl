// ps_3_0 shader decompiled by ps30
float3x3 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xyz = M._m01_m11_m21;
    r0.xyz = r0.yzx * M._m22_m02_m12 - (r0.zxy * M._m12_m22_m02);
    oC0 = dot(r0.xyz, M._m00_m10_m20) * texcoord0.x;
    return oC0;
}
