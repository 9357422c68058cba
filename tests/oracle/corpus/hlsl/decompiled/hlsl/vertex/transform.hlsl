// oracle: target=vs_2_0
// vs_2_0 shader decompiled by ps30
float3 light : register(c4);
float4x4 wvp : register(c0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
    float4 color0 : COLOR0;
    float4 texcoord0 : TEXCOORD0;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 normal0 : NORMAL0, float4 texcoord0 : TEXCOORD0)
{
    precise float4 oPos = 0, oD0 = 0, oT0 = 0;
    precise float4 r0 = 0;
    oPos = mul(position0, wvp);
    oD0 = min(max(dot(normal0.xyz, light), 0.0), 1.0);
    oT0.xy = texcoord0.xy + texcoord0.xy;
    VS_OUTPUT result;
    result.position0 = oPos;
    result.color0 = oD0;
    result.texcoord0 = oT0;
    return result;
}
