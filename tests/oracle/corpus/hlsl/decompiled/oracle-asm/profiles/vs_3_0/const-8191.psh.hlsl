// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float4 c8191 : register(c8191);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
};

VS_OUTPUT main(float4 position0 : POSITION0)
{
    precise float4 o0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    o0 = (float4(1.0, 0.5, 0.25, 2.0) + c8191);
    VS_OUTPUT result;
    result.position0 = o0;
    return result;
}
