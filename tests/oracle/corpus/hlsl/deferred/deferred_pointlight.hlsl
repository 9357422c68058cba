// Light volume pass for one point light: screen position from VPOS,
// position rebuilt from linear depth along a frustum ray.
sampler2D NormalBuf : register(s0);
sampler2D DepthBuf  : register(s1);
sampler2D ColorBuf  : register(s2);
float4 ScreenSize;       // xy = 1/size
float3 LightPosVS;
float  LightInvRadius;
float3 LightCol;
float3 FrustumCorner;

float4 main(float2 vpos : VPOS, float3 viewRay : TEXCOORD0) : COLOR
{
    float2 uv = (vpos + 0.5) * ScreenSize.xy;
    float z = tex2D(DepthBuf, uv).r;
    float3 P = viewRay * (z / viewRay.z);
    float3 N = normalize(tex2D(NormalBuf, uv).xyz * 2 - 1);
    float3 L = LightPosVS - P;
    float att = saturate(1 - length(L) * LightInvRadius);
    L = normalize(L);
    float3 albedo = tex2D(ColorBuf, uv).rgb;
    return float4(albedo * LightCol * saturate(dot(N, L)) * att * att, 0);
}
