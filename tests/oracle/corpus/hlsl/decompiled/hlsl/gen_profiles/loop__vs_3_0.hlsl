// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float4 k[8] : register(c0);
int4 n : register(i0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
};

VS_OUTPUT main(float4 position0 : POSITION0)
{
    precise float4 o0 = 0;
    precise float4 r0 = 0;
    r0 = position0;
    for (int i = 0; i < n.x; i++) {
        r0 = r0 + k[i];
    }
    o0 = r0;
    VS_OUTPUT result;
    result.position0 = o0;
    return result;
}
