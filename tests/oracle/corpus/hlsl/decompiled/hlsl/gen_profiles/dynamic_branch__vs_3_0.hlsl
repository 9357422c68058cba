// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float4 k : register(c0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
};

VS_OUTPUT main(float4 position0 : POSITION0)
{
    precise float4 o0 = 0;
    [branch] if (k.x < position0.x) {
        o0 = k * position0;
    } else {
        o0 = position0;
    }
    VS_OUTPUT result;
    result.position0 = o0;
    return result;
}
