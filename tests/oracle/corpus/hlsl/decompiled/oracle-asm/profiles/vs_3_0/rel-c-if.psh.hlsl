// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float4 c[224] : register(c0);

// c[i] as the shader reads it: c[0] is the shader's literal (def), the others the application's
float4 c_at(float i)
{
    [branch] if (i == 0)
        return float4(1.0, 0.5, 0.25, 2.0);
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
};

VS_OUTPUT main(float4 position0 : POSITION0)
{
    precise float4 o0 = 0;
    float4 a0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = float4(1.0, 0.5, 0.25, 2.0);
    r1 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    a0.x = mova_round(r1.x);
    [branch] if (c_at(a0.x).x > r1.x) {
        r0 = r1;
    }
    o0 = r0;
    VS_OUTPUT result;
    result.position0 = o0;
    return result;
}
