// Terrain: four layers blended by an RGBA splat map, each tiled separately.
sampler2D SplatMap : register(s0);
sampler2D Layer0   : register(s1);
sampler2D Layer1   : register(s2);
sampler2D Layer2   : register(s3);
sampler2D Layer3   : register(s4);
float4 LayerTiling;

float4 main(float2 uv : TEXCOORD0, float ndl : TEXCOORD1) : COLOR
{
    float4 w = tex2D(SplatMap, uv);
    w /= dot(w, 1);
    float3 c = tex2D(Layer0, uv * LayerTiling.x).rgb * w.r
             + tex2D(Layer1, uv * LayerTiling.y).rgb * w.g
             + tex2D(Layer2, uv * LayerTiling.z).rgb * w.b
             + tex2D(Layer3, uv * LayerTiling.w).rgb * w.a;
    return float4(c * saturate(ndl), 1);
}
