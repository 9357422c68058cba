// oracle: target=vs_2_a
// vs_2_x shader decompiled by ps30 (HLSL for vs_2_a)

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
};

VS_OUTPUT main(float4 position0 : POSITION0)
{
    precise float4 oPos = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r28 = 0, r29 = 0, r30 = 0, r31 = 0;
    r0 = float4(1.0, 0.5, 0.25, 2.0);
    r1 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    r28 = float4(1.0, 0.5, 0.25, 2.0);
    r29 = float4(1.0, 0.5, 0.25, 2.0);
    r30 = float4(1.0, 0.5, 0.25, 2.0);
    r31 = float4(1.0, 0.5, 0.25, 2.0);
    oPos = float4(dot(position0, r28), dot(position0, r29), dot(position0, r30), dot(position0, r31));
    VS_OUTPUT result;
    result.position0 = oPos;
    return result;
}
