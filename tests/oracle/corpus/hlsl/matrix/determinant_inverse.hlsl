// 3x3 inverse via cofactors and determinant().
float3x3 M;

float3x3 Inverse3(float3x3 m)
{
    float3 r0 = cross(m[1], m[2]);
    float3 r1 = cross(m[2], m[0]);
    float3 r2 = cross(m[0], m[1]);
    float inv = 1.0 / determinant(m);
    return transpose(float3x3(r0, r1, r2)) * inv;
}

float4 main(float3 v : TEXCOORD0) : COLOR
{
    return float4(mul(Inverse3(M), v), determinant(M));
}
