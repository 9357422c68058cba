// Inputs with NORMAL, TANGENT, BINORMAL, POSITION-less semantics that ps_3_0 allows.
float3 L;
float4 main(float3 n : NORMAL, float3 t : TANGENT, float3 b : BINORMAL, float4 c : COLOR0, float fog : FOG) : COLOR
{
    float3 N = normalize(n + t * 0.1 + b * 0.1);
    return c * saturate(dot(N, L)) * fog;
}
