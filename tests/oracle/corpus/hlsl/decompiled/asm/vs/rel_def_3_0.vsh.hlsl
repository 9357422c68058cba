// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float4 c[224] : register(c0);

// c[i] as the shader reads it: c[0]–c[1] are the shader's literals (def), the others the application's
float4 c_at(float i)
{
    [branch] if (i == 0)
        return float4(1.0, 0.5, -0.25, 0.0);
    [branch] if (i == 1)
        return float4(-2.0, 0.0, 3.0, 0.125);
    return c[i];
}

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
    float4 texcoord1 : TEXCOORD1;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 blendindices0 : BLENDINDICES0)
{
    precise float4 o0 = 0, o1 = 0, o2 = 0;
    float4 a0 = 0;
    a0.x = mova_round(blendindices0.x);
    o1 = c_at(a0.x);
    o2 = c_at(a0.x + 1) + position0;
    o0 = position0;
    VS_OUTPUT result;
    result.position0 = o0;
    result.texcoord0 = o1;
    result.texcoord1 = o2;
    return result;
}
