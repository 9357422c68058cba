// Four point lights in uniform arrays, accumulated in an unrolled loop.
#define NUM_LIGHTS 4

float4 LightPosRange[NUM_LIGHTS];   // xyz position, w = 1/range
float4 LightColour[NUM_LIGHTS];
sampler2D BaseMap;

float4 main(float2 uv : TEXCOORD0, float3 wpos : TEXCOORD1, float3 wnrm : TEXCOORD2) : COLOR
{
    float3 n = normalize(wnrm);
    float3 total = 0;
    [unroll]
    for (int i = 0; i < NUM_LIGHTS; i++)
    {
        float3 toL = LightPosRange[i].xyz - wpos;
        float dist = length(toL);
        float atten = saturate(1 - dist * LightPosRange[i].w);
        total += LightColour[i].rgb * saturate(dot(n, toL / dist)) * atten * atten;
    }
    return float4(tex2D(BaseMap, uv).rgb * total, 1);
}
