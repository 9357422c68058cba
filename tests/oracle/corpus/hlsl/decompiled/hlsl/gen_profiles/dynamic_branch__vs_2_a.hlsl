// oracle: target=vs_2_a
// vs_2_x shader decompiled by ps30 (HLSL for vs_2_a)
float4 k : register(c0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
};

VS_OUTPUT main(float4 position0 : POSITION0)
{
    precise float4 oPos = 0;
    [branch] if (k.x < position0.x) {
        oPos = position0 * k;
    } else {
        oPos = position0;
    }
    VS_OUTPUT result;
    result.position0 = oPos;
    return result;
}
