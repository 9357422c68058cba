// Arrays of row_major and column_major float3x4, indexed by a loop.
row_major float3x4 rowBones[4];
column_major float3x4 colBones[4];

float4 main(float4 v : TEXCOORD0, float4 w : TEXCOORD1) : COLOR
{
    float3 a = 0, b = 0;
    for (int i = 0; i < 4; i++)
    {
        a += mul(rowBones[i], v) * w[i];
        b += mul(colBones[i], v) * w[i];
    }
    return float4(a + b, 1);
}
