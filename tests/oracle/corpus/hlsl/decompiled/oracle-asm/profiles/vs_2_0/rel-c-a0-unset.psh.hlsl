// oracle: target=vs_2_0
// vs_2_0 shader decompiled by ps30
float4 c[224] : register(c0);

// c[i] as the shader reads it: c[0] is the shader's literal (def), the others the application's
float4 c_at(float i)
{
    precise float4 v = c[i];
    float s0 = i == 0 ? 1 : 0;
    v = v * (1 - s0) + float4(1.0, 0.5, 0.25, 2.0) * s0;
    return v;
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
    r1 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    oPos = c_at(a0.x);
    VS_OUTPUT result;
    result.position0 = oPos;
    return result;
}
