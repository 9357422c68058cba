// Iterative parallax: three refinement steps, unrolled.
sampler2D hMap;
sampler2D dMap;
float heightScale;

float4 main(float2 uv : TEXCOORD0, float3 eye : TEXCOORD1) : COLOR
{
    float3 e = normalize(eye);
    float2 t = uv;
    [unroll]
    for (int i = 0; i < 3; i++)
    {
        float4 nh = tex2D(hMap, t);
        t += (nh.a - 0.5) * heightScale * nh.z * e.xy;
    }
    return tex2D(dMap, t);
}
