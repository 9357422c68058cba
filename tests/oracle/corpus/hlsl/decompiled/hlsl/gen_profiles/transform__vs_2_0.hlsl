// oracle: target=vs_2_0
// vs_2_0 shader decompiled by ps30
float4x4 wvp : register(c0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
};

VS_OUTPUT main(float4 position0 : POSITION0)
{
    precise float4 oPos = 0;
    oPos = mul(position0, wvp);
    VS_OUTPUT result;
    result.position0 = oPos;
    return result;
}
