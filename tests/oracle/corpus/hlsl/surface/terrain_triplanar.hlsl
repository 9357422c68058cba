// Triplanar projection for cliffs, weights from the world normal.
sampler2D cliff : register(s0);
float tiling = 0.1;
float sharpness = 4;

float4 main(float3 P : TEXCOORD0, float3 N : TEXCOORD1) : COLOR
{
    float3 w = pow(abs(normalize(N)), sharpness);
    w /= w.x + w.y + w.z;
    float4 x = tex2D(cliff, P.zy * tiling);
    float4 y = tex2D(cliff, P.xz * tiling);
    float4 z = tex2D(cliff, P.xy * tiling);
    return x * w.x + y * w.y + z * w.z;
}
