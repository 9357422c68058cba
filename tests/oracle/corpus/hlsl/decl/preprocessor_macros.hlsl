// Preprocessor-driven variants as game shader systems write them.
#define USE_NORMALMAP 1
#define USE_FOG 1
#define SAMPLE(s, uv) tex2D(s, uv)
#define SATURATE3(x) clamp(x, 0.0, 1.0)
#if USE_NORMALMAP
sampler2D NormalMap : register(s1);
#endif
sampler2D BaseMap : register(s0);
float3 LightDir;
#if USE_FOG
float4 FogColor;
#endif

float4 main(float2 uv : TEXCOORD0, float3 n : TEXCOORD1, float fog : TEXCOORD2) : COLOR
{
#if USE_NORMALMAP
    float3 N = normalize(SAMPLE(NormalMap, uv).xyz * 2 - 1);
#else
    float3 N = normalize(n);
#endif
    float4 c = SAMPLE(BaseMap, uv);
    c.rgb *= SATURATE3(dot(N, LightDir));
#if USE_FOG
    c.rgb = lerp(FogColor.rgb, c.rgb, fog);
#endif
    return c;
}
