// oracle: target=vs_2_0
// vs_2_0 shader decompiled by ps30
float2 fogRange : register(c9);
float4 texTransform[2] : register(c7); // the table's type: float4x4
float4x3 world : register(c4);
float4x4 worldViewProj : register(c0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
    float4 texcoord0 : TEXCOORD0;
    float4 texcoord1 : TEXCOORD1;
    float fog0 : FOG0;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 normal0 : NORMAL0, float4 texcoord0 : TEXCOORD0)
{
    precise float4 oPos = 0, oT0 = 0, oT1 = 0, oFog = 0;
    precise float4 r0 = 0;
    oPos.x = dot(position0, worldViewProj._m00_m10_m20_m30);
    oPos.y = dot(position0, worldViewProj._m01_m11_m21_m31);
    oPos.w = dot(position0, worldViewProj._m03_m13_m23_m33);
    oT1.x = dot(normal0.xyz, world._m00_m10_m20);
    oT1.y = dot(normal0.xyz, world._m01_m11_m21);
    oT1.z = dot(normal0.xyz, world._m02_m12_m22);
    r0.xyz = texcoord0.xyx * float3(1.0, 1.0, 0.0) + float3(0.0, 0.0, 1.0);
    oT0.x = dot(r0.xyz, texTransform[0].xyz);
    oT0.y = dot(r0.xyz, texTransform[1].xyz);
    r0.x = 1.0 / (fogRange.y - fogRange.x);
    r0.y = dot(position0, worldViewProj._m02_m12_m22_m32);
    r0.z = fogRange.y - r0.y;
    oPos.z = r0.y;
    r0.x = r0.x * r0.z;
    oFog = min(max(r0.x, 0.0), 1.0);
    VS_OUTPUT result;
    result.position0 = oPos;
    result.texcoord0 = oT0;
    result.texcoord1 = oT1;
    result.fog0 = oFog.x;
    return result;
}
