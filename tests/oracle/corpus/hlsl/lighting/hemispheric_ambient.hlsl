// Hemispheric ambient: lerp between ground and sky colour by the normal's up component.
float3 SkyColor    = float3(0.4, 0.5, 0.7);
float3 GroundColor = float3(0.2, 0.15, 0.1);
float  AOStrength;
sampler2D AlbedoTexture;
sampler2D OcclusionTexture;

float4 main(float2 uv : TEXCOORD0, float3 normal : TEXCOORD1) : COLOR
{
    float up = normalize(normal).y * 0.5 + 0.5;
    float3 amb = lerp(GroundColor, SkyColor, up);
    float ao = lerp(1, tex2D(OcclusionTexture, uv).r, AOStrength);
    return float4(tex2D(AlbedoTexture, uv).rgb * amb * ao, 1);
}
