// oracle: target=vs_2_0
// Four-bone skinning from a float4x3 palette indexed by BLENDINDICES (mova through a0),
// with the weights from BLENDWEIGHT and the last one made up to 1.
float4x3 palette[24];
float4x4 viewProj;

struct Out
{
    float4 pos : POSITION;
    float3 normal : TEXCOORD0;
};

Out main(float4 pos : POSITION, float3 n : NORMAL, float4 idx : BLENDINDICES, float3 w : BLENDWEIGHT)
{
    float4 weights = float4(w, 1 - w.x - w.y - w.z);
    float3 p = 0, nn = 0;
    for (int k = 0; k < 4; k++)
    {
        p += mul(pos, palette[idx[k]]) * weights[k];
        nn += mul(n, (float3x3)palette[idx[k]]) * weights[k];
    }
    Out o;
    o.pos = mul(float4(p, 1), viewProj);
    o.normal = nn;
    return o;
}
