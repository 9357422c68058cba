// oracle: target=vs_2_0
// vs_2_0 shader decompiled by ps30
float4 bones[60] : register(c0); // the table's type: float4x3[20]
float4x4 vp : register(c60);

// mova's rounding: to the nearest integer, halves to even
float mova_round(float x)
{
    float a = abs(x);
    float f = frac(a);
    float r = a - f;
    return sign(x) * (r + (f > 0.5 || f == 0.5 && frac(r * 0.5) != 0 ? 1 : 0));
}

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 blendindices0 : BLENDINDICES0)
{
    precise float4 oPos = 0;
    float4 a0 = 0;
    precise float4 r0 = 0;
    r0.x = blendindices0.x < -blendindices0.x ? 1.0 : 0.0;
    r0.y = frac(blendindices0.x);
    r0.z = blendindices0.x - r0.y;
    r0.y = -r0.y < r0.y ? 1.0 : 0.0;
    r0.x = r0.x * r0.y + r0.z;
    a0.x = mova_round((r0.x * 3.0));
    r0.x = dot(position0, bones[a0.x]);
    r0.y = dot(position0, bones[a0.x + 1]);
    r0.z = dot(position0, bones[a0.x + 2]);
    r0.w = 1.0;
    oPos = mul(r0, vp);
    VS_OUTPUT result;
    result.position0 = oPos;
    return result;
}
