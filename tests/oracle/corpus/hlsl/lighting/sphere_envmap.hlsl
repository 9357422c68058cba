// Old-style sphere environment map looked up from the view-space normal.
sampler2D SphereMap;
sampler2D BaseTexture;
float EnvStrength;

float4 main(float2 uv : TEXCOORD0, float3 vsNormal : TEXCOORD1, float3 vsPos : TEXCOORD2) : COLOR
{
    float3 r = reflect(normalize(vsPos), normalize(vsNormal));
    float m = 2.0 * sqrt(r.x * r.x + r.y * r.y + (r.z + 1) * (r.z + 1));
    float2 sphUV = r.xy / m + 0.5;
    float4 base = tex2D(BaseTexture, uv);
    return base + tex2D(SphereMap, sphUV) * EnvStrength * base.a;
}
