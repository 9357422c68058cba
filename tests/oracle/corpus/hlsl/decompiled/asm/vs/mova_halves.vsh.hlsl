// oracle: target=vs_2_0
// vs_2_0 shader decompiled by ps30
float4 cr[215] : register(c9);

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
    float4 texcoord2 : TEXCOORD2;
    float4 texcoord3 : TEXCOORD3;
    float4 texcoord4 : TEXCOORD4;
};

VS_OUTPUT main(float4 position0 : POSITION0)
{
    precise float4 oPos = 0, oT0 = 0, oT1 = 0, oT2 = 0, oT3 = 0, oT4 = 0;
    float4 a0 = 0;
    a0.x = mova_round(0.5);
    oT0 = cr[a0.x];
    a0.x = mova_round(1.5);
    oT1 = cr[a0.x];
    a0.x = mova_round(2.5);
    oT2 = cr[a0.x];
    a0.x = mova_round(-0.5);
    oT3 = cr[a0.x + 2];
    a0.x = mova_round(-1.5);
    oT4 = cr[a0.x + 2];
    oPos = position0;
    VS_OUTPUT result;
    result.position0 = oPos;
    result.texcoord0 = oT0;
    result.texcoord1 = oT1;
    result.texcoord2 = oT2;
    result.texcoord3 = oT3;
    result.texcoord4 = oT4;
    return result;
}
