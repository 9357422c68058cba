// Two spot lights with smooth cone falloff (inner/outer cosines).
struct SpotLight
{
    float3 position;
    float3 direction;
    float3 color;
    float2 cosCone;      // x = cos(outer), y = cos(inner)
};

SpotLight g_Spots[2];
sampler2D g_Albedo;

float3 Spot(SpotLight s, float3 p, float3 n)
{
    float3 L = normalize(s.position - p);
    float cd = dot(-L, s.direction);
    float cone = smoothstep(s.cosCone.x, s.cosCone.y, cd);
    return s.color * cone * saturate(dot(n, L));
}

float4 main(float2 uv : TEXCOORD0, float3 p : TEXCOORD1, float3 n : TEXCOORD2) : COLOR
{
    n = normalize(n);
    float3 light = Spot(g_Spots[0], p, n) + Spot(g_Spots[1], p, n);
    return float4(tex2D(g_Albedo, uv).rgb * light, 1);
}
