// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float3 light : register(c4);
float4x4 wvp : register(c0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
    float4 color0 : COLOR0;
    float4 texcoord0 : TEXCOORD0;
    float fog0 : FOG0;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 normal0 : NORMAL0, float4 texcoord0 : TEXCOORD0)
{
    precise float4 o0 = 0, o1 = 0, o2 = 0, o3 = 0;
    precise float4 r0 = 0;
    o0.x = dot(position0, wvp._m00_m10_m20_m30);
    o0.y = dot(position0, wvp._m01_m11_m21_m31);
    o0.w = dot(position0, wvp._m03_m13_m23_m33);
    r0.x = dot(normal0.xyz, light);
    r0.y = -r0.x < r0.x ? 1.0 : 0.0;
    o1.y = r0.x * r0.y;
    o1.z = r0.y * 0.00390625;
    r0.x = dot(position0, wvp._m02_m12_m22_m32);
    o0.z = r0.x;
    o3.x = r0.x;
    o1.xw = 1.0;
    o2.xy = texcoord0.xy;
    VS_OUTPUT result;
    result.position0 = o0;
    result.color0 = o1;
    result.texcoord0 = o2;
    result.fog0 = o3.x;
    return result;
}
