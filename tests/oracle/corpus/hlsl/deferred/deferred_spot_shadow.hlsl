// Deferred spot light with a projected shadow map and a cookie texture.
sampler2D gb_normal : register(s0);
sampler2D gb_depth  : register(s1);
sampler2D shadowMap : register(s2);
sampler2D cookie    : register(s3);
float4x4 viewToLight;
float3 spotPos, spotDir, spotColor;
float2 spotCos;
float shadowBias = 0.002;

float4 main(float4 scr : TEXCOORD0, float3 ray : TEXCOORD1) : COLOR
{
    float2 uv = scr.xy / scr.w;
    float3 P = ray * tex2D(gb_depth, uv).r;
    float3 N = tex2D(gb_normal, uv).xyz * 2 - 1;
    float3 L = normalize(spotPos - P);
    float cone = saturate((dot(-L, spotDir) - spotCos.x) / (spotCos.y - spotCos.x));
    float4 lp = mul(float4(P, 1), viewToLight);
    float2 suv = lp.xy / lp.w * float2(0.5, -0.5) + 0.5;
    float lit = (lp.z / lp.w - shadowBias) < tex2D(shadowMap, suv).r;
    float3 ck = tex2D(cookie, suv).rgb;
    return float4(spotColor * ck * cone * lit * saturate(dot(N, L)), 1);
}
