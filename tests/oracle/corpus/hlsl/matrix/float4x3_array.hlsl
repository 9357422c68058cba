// Skinning-style palette: float4x3 bones indexed by per-pixel (interpolated) indices.
float4x3 Bones[20];

float4 main(float4 pos : TEXCOORD0, float4 weights : TEXCOORD1, float4 indices : TEXCOORD2) : COLOR
{
    int4 idx = (int4)indices;
    float3 p = mul(pos, Bones[idx.x]) * weights.x;
    p += mul(pos, Bones[idx.y]) * weights.y;
    p += mul(pos, Bones[idx.z]) * weights.z;
    p += mul(pos, Bones[idx.w]) * (1 - weights.x - weights.y - weights.z);
    return float4(p, 1);
}
