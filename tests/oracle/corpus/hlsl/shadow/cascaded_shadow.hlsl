// Three-cascade shadow map in one atlas, cascade picked by view depth.
sampler2D cascadeAtlas : register(s4);
float4x4 cascadeMatrix[3];
float3   cascadeSplits;     // far distance of each cascade
float    atlasBias[3];

float4 main(float4 worldPos : TEXCOORD0, float viewDepth : TEXCOORD1) : COLOR
{
    int idx = 2;
    if (viewDepth < cascadeSplits.y) idx = 1;
    if (viewDepth < cascadeSplits.x) idx = 0;
    float4 lp = mul(worldPos, cascadeMatrix[idx]);
    float2 uv = lp.xy * float2(0.5 / 3, -0.5) + float2((idx + 0.5) / 3, 0.5);
    float d = tex2D(cascadeAtlas, uv).r;
    float lit = lp.z - atlasBias[idx] < d;
    return float4(lit, idx / 2.0, 0, 1);
}
