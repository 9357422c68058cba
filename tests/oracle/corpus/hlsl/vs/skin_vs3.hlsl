// oracle: target=vs_3_0
// vs_3_0 skinning with two bones from a row_major float4x3 palette, tangent frame out.
row_major float4x3 bones[30];
float4x4 viewProj;

struct Out
{
    float4 pos : POSITION;
    float3 tangent : TEXCOORD0;
    float3 normal : TEXCOORD1;
};

Out main(float4 pos : POSITION, float3 n : NORMAL, float3 t : TANGENT, float4 idx : BLENDINDICES, float4 w : BLENDWEIGHT)
{
    float4x3 m = bones[idx.x] * w.x + bones[idx.y] * (1 - w.x);
    Out o;
    o.pos = mul(float4(mul(pos, m), 1), viewProj);
    o.normal = normalize(mul(n, (float3x3)m));
    o.tangent = normalize(mul(t, (float3x3)m));
    return o;
}
