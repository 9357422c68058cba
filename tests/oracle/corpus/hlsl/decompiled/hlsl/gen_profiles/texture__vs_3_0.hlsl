// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
sampler2D s : register(s0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
};

VS_OUTPUT main(float4 position0 : POSITION0)
{
    precise float4 o0 = 0;
    precise float4 r0 = 0;
    o0 = tex2Dlod(s, (float4(1.0, 1.0, 0.0, 0.0) * position0.xyxx)) + position0;
    VS_OUTPUT result;
    result.position0 = o0;
    return result;
}
