// Normal transform with the upper 3x3 of a matrix and its transpose.
float4x4 worldMatrix;
float3x3 normalMatrix;

float4 main(float3 n : TEXCOORD0, float3 t : TEXCOORD1) : COLOR
{
    float3 a = mul(n, (float3x3)worldMatrix);
    float3 b = mul(transpose(normalMatrix), t);
    float3 c = mul(normalMatrix, t);
    return float4(normalize(a) + normalize(b) * c, 1);
}
