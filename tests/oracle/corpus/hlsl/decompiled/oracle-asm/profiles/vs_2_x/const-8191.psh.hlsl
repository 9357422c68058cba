// oracle: target=vs_2_a
// vs_2_x shader decompiled by ps30 (HLSL for vs_2_a)
float4 c8191 : register(c8191);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
};

VS_OUTPUT main(float4 position0 : POSITION0)
{
    precise float4 oPos = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    oPos = (float4(1.0, 0.5, 0.25, 2.0) + c8191);
    VS_OUTPUT result;
    result.position0 = oPos;
    return result;
}
