// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float4 bones[120] : register(c0); // the table's type: row_major float4x3[30]
float4x4 viewProj : register(c120);

// mova's rounding: to the nearest integer, halves to even
float2 mova_round(float2 x)
{
    float2 a = abs(x);
    float2 f = frac(a);
    float2 r = a - f;
    return sign(x) * (r + (f > 0.5 || f == 0.5 && frac(r * 0.5) != 0 ? 1 : 0));
}

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
    float4 texcoord0 : TEXCOORD0;
    float4 texcoord1 : TEXCOORD1;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 normal0 : NORMAL0, float4 tangent0 : TANGENT0, float4 blendindices0 : BLENDINDICES0, float4 blendweight0 : BLENDWEIGHT0)
{
    precise float4 o0 = 0, o1 = 0, o2 = 0;
    float4 a0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0, r6 = 0, r7 = 0, r8 = 0;
    r0.xy = blendindices0.xy - frac(blendindices0.xy);
    a0.xy = mova_round((r0.xy * 4.0));
    r0.x = blendweight0.x * bones[a0.x + 2].z;
    r0.yzw = blendweight0.x * bones[a0.x + 3].xyz;
    r1.zw = r0.xw;
    r0.x = 1.0 - blendweight0.x;
    r2.x = r0.x * bones[a0.y + 2].z;
    r2.yzw = r0.x * bones[a0.y + 3].xyz;
    r3.zw = r2.xw;
    r4.xyz = blendweight0.x * bones[a0.x].yxz;
    r1.x = r4.z;
    r5.xyz = blendweight0.x * bones[a0.x + 1].xyz;
    r2.xw = blendweight0.x * bones[a0.x + 2].xy;
    r1.y = r5.z;
    r6.xyz = r0.x * bones[a0.y].yxz;
    r3.x = r6.z;
    r7.xyz = r0.x * bones[a0.y + 1].xyz;
    r0.xw = r0.x * bones[a0.y + 2].xy;
    r3.y = r7.z;
    r1 = r1 + r3;
    r3.z = dot(position0, r1);
    r8.x = r6.y;
    r8.y = r7.x;
    r6.y = r7.y;
    r8.z = r0.x;
    r6.z = r0.w;
    r8.w = r2.y;
    r6.w = r2.z;
    r7.x = r4.y;
    r7.y = r5.x;
    r4.y = r5.y;
    r7.z = r2.x;
    r4.z = r2.w;
    r7.w = r0.y;
    r4.w = r0.z;
    r0 = r6 + r4;
    r2 = r8 + r7;
    r3.x = dot(position0, r2);
    r3.y = dot(position0, r0);
    r3.w = 1.0;
    o0 = mul(r3, viewProj);
    r3.x = dot(normal0.xyz, r2.xyz);
    r2.x = dot(tangent0.xyz, r2.xyz);
    r3.y = dot(normal0.xyz, r0.xyz);
    r2.y = dot(tangent0.xyz, r0.xyz);
    r3.z = dot(normal0.xyz, r1.xyz);
    r2.z = dot(tangent0.xyz, r1.xyz);
    o2.xyz = rsqrt(abs(dot(r3.xyz, r3.xyz))) * r3.xyz;
    o1.xyz = rsqrt(abs(dot(r2.xyz, r2.xyz))) * r2.xyz;
    VS_OUTPUT result;
    result.position0 = o0;
    result.texcoord0 = o1;
    result.texcoord1 = o2;
    return result;
}
