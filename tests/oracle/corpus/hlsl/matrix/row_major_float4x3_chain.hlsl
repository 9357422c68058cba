// A row_major float4x3 bone followed by a row_major float3x3 rotation:
// chains of three-component rows.
row_major float4x3 Bone;
row_major float3x3 Rotation;
float4 tint;

float4 main(float4 p : TEXCOORD0) : COLOR
{
    float3 q = mul(mul(p, Bone), Rotation);
    return float4(q, 1) * tint;
}
