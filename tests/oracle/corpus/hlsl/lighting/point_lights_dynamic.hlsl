// Up to eight point lights; the count arrives as an int constant and the loop
// is left as a real loop.
float4 lightPos[8];
float4 lightCol[8];
int    lightCount;
float3 ambient;

float4 main(float3 P : TEXCOORD0, float3 N : TEXCOORD1, float4 albedo : COLOR0) : COLOR
{
    float3 n = normalize(N);
    float3 acc = ambient;
    [loop]
    for (int i = 0; i < lightCount; ++i)
    {
        float3 L = lightPos[i].xyz - P;
        float inv = rsqrt(dot(L, L));
        float att = 1.0 / (1.0 + lightPos[i].w * dot(L, L));
        acc += lightCol[i].rgb * max(0, dot(n, L * inv)) * att;
    }
    return float4(albedo.rgb * acc, albedo.a);
}
