// Single directional light, Lambert diffuse, plain vertex colour.
float3 LightDir;      // world space, points toward the light
float3 LightColor;
float3 AmbientColor;
sampler2D DiffuseMap;

struct PS_IN
{
    float2 uv     : TEXCOORD0;
    float3 normal : TEXCOORD1;
    float4 color  : COLOR0;
};

float4 main(PS_IN i) : COLOR
{
    float3 n = normalize(i.normal);
    float ndl = saturate(dot(n, LightDir));
    float4 albedo = tex2D(DiffuseMap, i.uv) * i.color;
    albedo.rgb *= AmbientColor + LightColor * ndl;
    return albedo;
}
