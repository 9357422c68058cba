// Fixed-function style lighting through the lit() intrinsic.
float4 LightDirection;
float4 MaterialDiffuse;
float4 MaterialSpecular;
float  Shininess;

float4 main(float3 N : TEXCOORD0, float3 H : TEXCOORD1) : COLOR
{
    float3 n = normalize(N);
    float4 l = lit(dot(n, LightDirection.xyz), dot(n, normalize(H)), Shininess);
    return MaterialDiffuse * l.y + MaterialSpecular * l.z;
}
