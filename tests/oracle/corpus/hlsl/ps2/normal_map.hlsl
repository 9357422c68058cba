// oracle: target=ps_2_0
// Tangent-space normal mapping with one directional light given in tangent space by the
// vertex shader, and a Blinn-Phong highlight with a fixed power.
sampler2D diffuseMap : register(s0);
sampler2D normalMap : register(s1);
float4 lightColor;
float specPower;

float4 main(float2 uv : TEXCOORD0, float3 lightT : TEXCOORD1, float3 halfT : TEXCOORD2) : COLOR
{
    float3 n = normalize(tex2D(normalMap, uv).xyz * 2 - 1);
    float3 l = normalize(lightT);
    float3 h = normalize(halfT);
    float ndl = saturate(dot(n, l));
    float spec = pow(saturate(dot(n, h)), specPower);
    float4 albedo = tex2D(diffuseMap, uv);
    return float4(albedo.rgb * lightColor.rgb * ndl + spec * lightColor.a, albedo.a);
}
