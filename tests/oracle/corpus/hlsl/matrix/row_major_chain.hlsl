// mul(mul(v, World), ViewProj) with row_major matrices: each product a
// sum of rows weighted by the vector's components (mul and mad chains).
row_major float4x4 World;
row_major float4x4 ViewProj;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    return mul(mul(v, World), ViewProj);
}
