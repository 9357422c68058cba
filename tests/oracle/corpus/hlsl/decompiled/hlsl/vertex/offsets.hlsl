// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float4 offsets[6] : register(c0);
int4 count : register(i0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
    float4 texcoord1 : TEXCOORD1;
};

VS_OUTPUT main(float4 position0 : POSITION0)
{
    precise float4 o0 = 0, o1 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = position0;
    for (int i = 0; i < count.x; i++) {
        r0 = r0 + offsets[i];
    }
    o0 = r0;
    o1 = (-position0 < position0 ? 1.0 : 0.0) - (position0 < -position0 ? 1.0 : 0.0);
    VS_OUTPUT result;
    result.position0 = o0;
    result.texcoord1 = o1;
    return result;
}
