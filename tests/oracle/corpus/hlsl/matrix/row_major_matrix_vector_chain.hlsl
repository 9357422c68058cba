// mul(B, mul(A, v)) with row_major matrices: dot products against rows,
// the matrix as the first operand; and the column-major mul(M, v) chain.
row_major float4x4 A;
row_major float4x4 B;
float4x4 C;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    return mul(B, mul(A, v)) + mul(C, mul(C, v));
}
