// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float4 cr[220] : register(c4);

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
    float4 texcoord0 : TEXCOORD0;
    float4 texcoord1 : TEXCOORD1;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 blendindices0 : BLENDINDICES0)
{
    precise float4 o0 = 0, o1 = 0, o2 = 0;
    float4 a0 = 0;
    a0.xy = mova_round(blendindices0.xy);
    o1 = cr[a0.x];
    a0.zw = mova_round(-blendindices0.yy);
    o2 = cr[a0.w + 4];
    o0 = position0;
    VS_OUTPUT result;
    result.position0 = o0;
    result.texcoord0 = o1;
    result.texcoord1 = o2;
    return result;
}
