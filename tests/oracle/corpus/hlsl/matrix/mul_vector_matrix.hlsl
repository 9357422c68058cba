// mul(v, M) and mul(M, v) with the default (column_major) packing.
float4x4 World;
float4x4 ViewProj;

float4 main(float4 p : TEXCOORD0) : COLOR
{
    float4 a = mul(p, World);       // row vector
    float4 b = mul(ViewProj, a);    // column vector
    return a * 0.5 + b;
}
