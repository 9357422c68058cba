// oracle: target=vs_2_0
// vs_2_0 shader decompiled by ps30
float4 c[224] : register(c0);

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
    float4 texcoord0 : TEXCOORD0;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 texcoord0 : TEXCOORD0, float4 blendindices0 : BLENDINDICES0)
{
    precise float4 oPos = 0, oT0 = 0;
    float4 a0 = 0;
    a0.x = mova_round(blendindices0.x);
    oPos = float4(dot(position0, c[a0.x]), dot(position0, c[a0.x + 1]), dot(position0, c[a0.x + 2]), dot(position0, c[a0.x + 3]));
    oT0 = texcoord0;
    VS_OUTPUT result;
    result.position0 = oPos;
    result.texcoord0 = oT0;
    return result;
}
