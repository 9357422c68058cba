// Final combine: albedo * (light accumulation) + emissive, with fog from depth.
sampler2D albedoRT : register(s0);
sampler2D lightRT  : register(s1);
sampler2D depthRT  : register(s2);
float3 fogColour;
float  fogDensity;

float4 main(float2 uv : TEXCOORD0) : COLOR0
{
    float4 a = tex2D(albedoRT, uv);
    float4 l = tex2D(lightRT, uv);
    float  d = tex2D(depthRT, uv).x;
    float3 lit = a.rgb * l.rgb + l.a * a.rgb; // a.rgb * spec in alpha
    float fog = 1 - exp(-d * fogDensity);
    return float4(lerp(lit, fogColour, fog), 1);
}
