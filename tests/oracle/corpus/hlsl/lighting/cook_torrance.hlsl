// Cook-Torrance microfacet specular: Beckmann distribution, Schlick Fresnel,
// Cook-Torrance geometric term.
#define PI 3.14159265

sampler2D albedoTex : register(s0);
float3 lightDirection;
float3 lightRadiance;
float3 cameraPos;
float  roughness = 0.4;
float  F0        = 0.04;

float Beckmann(float NdotH, float m)
{
    float m2 = m * m;
    float c2 = NdotH * NdotH;
    float t  = (c2 - 1) / (m2 * c2);
    return exp(t) / (PI * m2 * c2 * c2);
}

float Fresnel(float VdotH)
{
    return F0 + (1 - F0) * pow(1 - VdotH, 5);
}

float4 main(float2 uv : TEXCOORD0, float3 pos : TEXCOORD1, float3 nrm : TEXCOORD2) : COLOR
{
    float3 N = normalize(nrm);
    float3 V = normalize(cameraPos - pos);
    float3 L = lightDirection;
    float3 H = normalize(L + V);

    float NdotL = saturate(dot(N, L));
    float NdotV = saturate(dot(N, V)) + 1e-4;
    float NdotH = saturate(dot(N, H));
    float VdotH = saturate(dot(V, H));

    float G = min(1, min(2 * NdotH * NdotV / VdotH, 2 * NdotH * NdotL / VdotH));
    float D = Beckmann(NdotH, roughness);
    float spec = D * Fresnel(VdotH) * G / (4 * NdotV);

    float3 base = tex2D(albedoTex, uv).rgb;
    return float4((base / PI + spec) * lightRadiance * NdotL, 1);
}
