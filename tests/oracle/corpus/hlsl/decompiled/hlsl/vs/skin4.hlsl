// oracle: target=vs_2_0
// vs_2_0 shader decompiled by ps30
float4 palette[72] : register(c0); // the table's type: float4x3[24]
float4x4 viewProj : register(c72);

// mova's rounding: to the nearest integer, halves to even
float4 mova_round(float4 x)
{
    float4 a = abs(x);
    float4 f = frac(a);
    float4 r = a - f;
    return sign(x) * (r + (f > 0.5 || f == 0.5 && frac(r * 0.5) != 0 ? 1 : 0));
}

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
    float4 texcoord0 : TEXCOORD0;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 normal0 : NORMAL0, float4 blendindices0 : BLENDINDICES0, float4 blendweight0 : BLENDWEIGHT0)
{
    precise float4 oPos = 0, oT0 = 0;
    float4 a0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.x = ((1.0 - blendweight0.x) - blendweight0.y) - blendweight0.z;
    r1 = blendindices0 - frac(blendindices0);
    a0 = mova_round((r1 * 3.0).yxzw);
    r2.x = dot(normal0.xyz, palette[a0.x].xyz);
    r2.y = dot(normal0.xyz, palette[a0.x + 1].xyz);
    r2.z = dot(normal0.xyz, palette[a0.x + 2].xyz);
    r0.yzw = r2.xyz * blendweight0.y;
    r2.x = dot(normal0.xyz, palette[a0.y].xyz);
    r2.y = dot(normal0.xyz, palette[a0.y + 1].xyz);
    r2.z = dot(normal0.xyz, palette[a0.y + 2].xyz);
    r1.x = dot(normal0.xyz, palette[a0.z].xyz);
    r1.y = dot(normal0.xyz, palette[a0.z + 1].xyz);
    r1.z = dot(normal0.xyz, palette[a0.z + 2].xyz);
    r0.yzw = r1.xyz * blendweight0.z + (r2.xyz * blendweight0.x + r0.yzw);
    r1.x = dot(normal0.xyz, palette[a0.w].xyz);
    r1.y = dot(normal0.xyz, palette[a0.w + 1].xyz);
    r1.z = dot(normal0.xyz, palette[a0.w + 2].xyz);
    oT0.xyz = r1.xyz * r0.x + r0.yzw;
    r1.x = dot(position0, palette[a0.x]);
    r1.y = dot(position0, palette[a0.x + 1]);
    r1.z = dot(position0, palette[a0.x + 2]);
    r0.yzw = r1.xyz * blendweight0.y;
    r1.x = dot(position0, palette[a0.y]);
    r1.y = dot(position0, palette[a0.y + 1]);
    r1.z = dot(position0, palette[a0.y + 2]);
    r0.yzw = r1.xyz * blendweight0.x + r0.yzw;
    r1.x = dot(position0, palette[a0.z]);
    r1.y = dot(position0, palette[a0.z + 1]);
    r1.z = dot(position0, palette[a0.z + 2]);
    r0.yzw = r1.xyz * blendweight0.z + r0.yzw;
    r1.x = dot(position0, palette[a0.w]);
    r1.y = dot(position0, palette[a0.w + 1]);
    r1.z = dot(position0, palette[a0.w + 2]);
    r0.xyz = r1.xyz * r0.x + r0.yzw;
    r0.w = 1.0;
    oPos = mul(r0, viewProj);
    VS_OUTPUT result;
    result.position0 = oPos;
    result.texcoord0 = oT0;
    return result;
}
