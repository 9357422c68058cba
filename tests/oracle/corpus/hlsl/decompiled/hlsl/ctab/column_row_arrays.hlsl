// ps_3_0 shader decompiled by ps30
float3x4 colBones[4] : register(c0);
row_major float3x4 rowBones[4] : register(c16);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = mul(colBones[0], texcoord0) * texcoord1.x + (mul(colBones[1], texcoord0) * texcoord1.y);
    r0.xyz = mul(colBones[2], texcoord0) * texcoord1.z + r0.xyz;
    r0.xyz = mul(colBones[3], texcoord0) * texcoord1.w + r0.xyz;
    r1.x = dot(rowBones[1][0], texcoord0);
    r1.y = dot(rowBones[1][1], texcoord0);
    r1.z = dot(rowBones[1][2], texcoord0);
    r2.x = dot(rowBones[0][0], texcoord0);
    r2.y = dot(rowBones[0][1], texcoord0);
    r2.z = dot(rowBones[0][2], texcoord0);
    r1.xyz = r2.xyz * texcoord1.x + (r1.xyz * texcoord1.y);
    r2.x = dot(rowBones[2][0], texcoord0);
    r2.y = dot(rowBones[2][1], texcoord0);
    r2.z = dot(rowBones[2][2], texcoord0);
    r1.xyz = r2.xyz * texcoord1.z + r1.xyz;
    r2.x = dot(rowBones[3][0], texcoord0);
    r2.y = dot(rowBones[3][1], texcoord0);
    r2.z = dot(rowBones[3][2], texcoord0);
    oC0.xyz = r0.xyz + (r2.xyz * texcoord1.w + r1.xyz);
    oC0.w = 1.0;
    return oC0;
}
