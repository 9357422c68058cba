// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float4 bones[24] : register(c0); // the table's type: float4x3[8]
float4x4 vp : register(c24);

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
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 blendindices0 : BLENDINDICES0, float4 blendweight0 : BLENDWEIGHT0, float4 texcoord0 : TEXCOORD0)
{
    float4 o0 = 0, o1 = 0;
    float4 a0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xy = blendindices0.xy < -blendindices0.xy ? 1.0 : 0.0;
    r0.zw = frac(blendindices0.xy);
    r1.xy = blendindices0.xy - r0.zw;
    r0.zw = -r0.zw < r0.zw ? 1.0 : 0.0;
    r0.xy = r0.xy * r0.zw + r1.xy;
    a0.xy = mova_round((r0.xy * 3.0));
    r0.x = dot(position0, bones[a0.x]);
    r0.y = dot(position0, bones[a0.x + 1]);
    r0.z = dot(position0, bones[a0.x + 2]);
    r1.x = dot(position0, bones[a0.y]);
    r1.y = dot(position0, bones[a0.y + 1]);
    r1.z = dot(position0, bones[a0.y + 2]);
    r2.xyz = lerp(r1.xyz, r0.xyz, blendweight0.x);
    r2.w = 1.0;
    o0 = mul(r2, vp);
    o1.xy = texcoord0.xy;
    VS_OUTPUT result;
    result.position0 = o0;
    result.texcoord0 = o1;
    return result;
}
