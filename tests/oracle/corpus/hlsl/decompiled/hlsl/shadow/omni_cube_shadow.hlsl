// ps_3_0 shader decompiled by ps30
float3 lightCol : register(c2);
float3 lightPosition : register(c0);
float lightRangeInv : register(c1);
samplerCUBE distCube : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = normalize(texcoord1.xyz);
    r1.xyz = texcoord0.xyz - lightPosition;
    r0.w = rsqrt(abs(dot(r1.xyz, r1.xyz)));
    r2.xyz = r0.w * -r1.xyz;
    r0.w = 1.0 / r0.w;
    r1 = texCUBE(distCube, r1.xyz);
    r0.xyz = saturate(dot(r0.xyz, r2.xyz)) * lightCol;
    r2.xz = float2(-0.01, 1.0);
    r1.y = r0.w * lightRangeInv + r2.x;
    r0.w = r0.w * -lightRangeInv + r2.z;
    r0.xyz = (r1.y - r1.x) >= 0.0 ? 0.0 : r0.xyz;
    oC0.xyz = r0.w * r0.xyz;
    oC0.w = 1.0;
    return oC0;
}
