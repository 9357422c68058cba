// Variance shadow map: Chebyshev upper bound with light-bleed reduction.
sampler2D momentsMap;
float minVariance = 0.00002;
float bleedReduce = 0.2;

float Chebyshev(float2 m, float t)
{
    float p = t <= m.x;
    float variance = max(m.y - m.x * m.x, minVariance);
    float d = t - m.x;
    float pmax = variance / (variance + d * d);
    pmax = saturate((pmax - bleedReduce) / (1 - bleedReduce));
    return max(p, pmax);
}

float4 main(float4 lightSpace : TEXCOORD0) : COLOR
{
    float2 uv = lightSpace.xy / lightSpace.w;
    float2 moments = tex2D(momentsMap, uv).rg;
    return Chebyshev(moments, lightSpace.z / lightSpace.w);
}
