// Environment reflection from a cube map with a Schlick fresnel blend.
samplerCUBE EnvMap : register(s2);
sampler2D   Diffuse : register(s0);
float3 EyePosition;
float  ReflectAmount = 0.6;

float4 main(float2 uv : TEXCOORD0, float3 worldPos : TEXCOORD1, float3 worldNormal : TEXCOORD2) : COLOR
{
    float3 N = normalize(worldNormal);
    float3 I = normalize(worldPos - EyePosition);
    float3 R = reflect(I, N);
    float fres = 0.05 + 0.95 * pow(1 - saturate(dot(-I, N)), 5);
    float3 env = texCUBE(EnvMap, R).rgb;
    float3 base = tex2D(Diffuse, uv).rgb;
    return float4(lerp(base, env, fres * ReflectAmount), 1);
}
