// oracle: target=vs_3_0
// Two-bone skinning from a float4x3 palette indexed by BLENDINDICES (relative constant reads
// through a0), weighted by BLENDWEIGHT, then a view-projection matrix.
float4x3 bones[8] : register(c0);
float4x4 vp : register(c24);

struct VOut {
    float4 pos : POSITION;
    float2 uv : TEXCOORD0;
};

VOut main(float4 p : POSITION, float4 idx : BLENDINDICES, float4 w : BLENDWEIGHT, float2 uv : TEXCOORD0) {
    float3 a = mul(p, bones[(int)idx.x]);
    float3 b = mul(p, bones[(int)idx.y]);
    float3 s = a * w.x + b * (1 - w.x);
    VOut o;
    o.pos = mul(float4(s, 1), vp);
    o.uv = uv;
    return o;
}
