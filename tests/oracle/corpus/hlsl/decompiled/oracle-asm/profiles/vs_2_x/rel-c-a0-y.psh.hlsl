// oracle: target=vs_2_a
// vs_2_x shader decompiled by ps30 (HLSL for vs_2_a)
float4 cr[223] : register(c1);

// mova's rounding: to the nearest integer, halves to even
float2 mova_round(float2 x)
{
    float2 a = abs(x);
    float2 f = frac(a);
    float2 r = a - f;
    return sign(x) * (r + (f > 0.5 || f == 0.5 && frac(r * 0.5) != 0 ? 1 : 0));
}

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
};

VS_OUTPUT main(float4 position0 : POSITION0)
{
    precise float4 oPos = 0;
    float4 a0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    a0.xy = mova_round(float4(1.0, 0.5, 0.25, 2.0).xy);
    oPos = (-cr[a0.y].yzxw);
    VS_OUTPUT result;
    result.position0 = oPos;
    return result;
}
