// The same products with row_major matrices: dp4 against rows versus mad chains.
row_major float4x4 matRM;
column_major float4x4 matCM;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    return mul(v, matRM) + mul(v, matCM) + mul(matRM, v) + mul(matCM, v);
}
