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
    o0 = c_at(a0.x);
    VS_OUTPUT result;
    result.position0 = o0;
    return result;
}
