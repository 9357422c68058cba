// Simple parallax offset mapping with offset limiting.
sampler2D heightMap : register(s2);
sampler2D colorMap  : register(s0);
sampler2D normalMap : register(s1);
float2 scaleBias = float2(0.04, -0.02);
float3 lightTS;

float4 main(float2 uv : TEXCOORD0, float3 viewTS : TEXCOORD1) : COLOR
{
    float3 v = normalize(viewTS);
    float h = tex2D(heightMap, uv).r * scaleBias.x + scaleBias.y;
    float2 tc = uv + h * v.xy;
    float3 n = normalize(tex2D(normalMap, tc).xyz * 2 - 1);
    return tex2D(colorMap, tc) * saturate(dot(n, normalize(lightTS)));
}
