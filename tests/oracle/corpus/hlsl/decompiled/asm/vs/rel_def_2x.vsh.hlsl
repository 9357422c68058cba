// oracle: target=vs_2_a
// vs_2_x shader decompiled by ps30 (HLSL for vs_2_a)
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
    precise float4 oPos = 0, oT0 = 0, oT1 = 0;
    float4 a0 = 0;
    a0.x = mova_round(blendindices0.x);
    oT0 = c_at(a0.x);
    oT1 = c_at(a0.x + 1) + position0;
    oPos = position0;
    VS_OUTPUT result;
    result.position0 = oPos;
    result.texcoord0 = oT0;
    result.texcoord1 = oT1;
    return result;
}
