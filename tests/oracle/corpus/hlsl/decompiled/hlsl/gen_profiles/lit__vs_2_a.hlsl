// oracle: target=vs_2_a
// vs_2_x shader decompiled by ps30 (HLSL for vs_2_a)
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
    precise float4 oPos = 0, oD0 = 0, oT0 = 0, oFog = 0;
    precise float4 r0 = 0;
    oPos.x = dot(position0, wvp._m00_m10_m20_m30);
    oPos.y = dot(position0, wvp._m01_m11_m21_m31);
    oPos.w = dot(position0, wvp._m03_m13_m23_m33);
    r0.x = dot(normal0.xyz, light);
    r0.yzw = float3(0.5, 8.0, 8.0);
    oD0 = lit(r0.x, r0.y, r0.w);
    r0.x = dot(position0, wvp._m02_m12_m22_m32);
    oPos.z = r0.x;
    oFog = r0.x;
    oT0.xy = texcoord0.xy;
    VS_OUTPUT result;
    result.position0 = oPos;
    result.color0 = oD0;
    result.texcoord0 = oT0;
    result.fog0 = oFog.x;
    return result;
}
