// Forward "uber" material as engines build them: one source, permutation macros set at the top
// (this file is the all-features permutation), four lights, shadow, fog, emissive, detail.
#define NUM_LIGHTS   4
#define HAS_NORMAL   1
#define HAS_SHADOW   1
#define HAS_DETAIL   1
#define HAS_EMISSIVE 1
#define HAS_FOG      1

sampler2D s_Albedo   : register(s0);
sampler2D s_Normal   : register(s1);
sampler2D s_Spec     : register(s2);
sampler2D s_Shadow   : register(s3);
sampler2D s_Detail   : register(s4);
sampler2D s_Emissive : register(s5);

cbuffer PerFrame
{
    float3 u_EyePos;
    float4 u_FogColorDensity;
    float4 u_ShadowTexel;
};
cbuffer PerMaterial
{
    float4 u_Tint;
    float  u_Gloss;
    float  u_DetailTile;
    float3 u_EmissiveScale;
};
float4 u_LightPos[NUM_LIGHTS];
float4 u_LightCol[NUM_LIGHTS];

struct VOut
{
    float2 uv       : TEXCOORD0;
    float3 worldPos : TEXCOORD1;
    float3 t        : TEXCOORD2;
    float3 b        : TEXCOORD3;
    float3 n        : TEXCOORD4;
    float4 shadowUV : TEXCOORD5;
};

float ShadowTerm(float4 sc)
{
#if HAS_SHADOW
    float3 p = sc.xyz / sc.w;
    float s = 0;
    [unroll] for (int y = 0; y < 2; y++)
        [unroll] for (int x = 0; x < 2; x++)
            s += p.z <= tex2D(s_Shadow, p.xy + (float2(x, y) - 0.5) * u_ShadowTexel.xy).r;
    return s * 0.25;
#else
    return 1;
#endif
}

float4 main(VOut i) : COLOR
{
    float4 albedo = tex2D(s_Albedo, i.uv) * u_Tint;
#if HAS_DETAIL
    albedo.rgb *= tex2D(s_Detail, i.uv * u_DetailTile).rgb * 2;
#endif
#if HAS_NORMAL
    float3 tn = tex2D(s_Normal, i.uv).xyz * 2 - 1;
    float3 N = normalize(tn.x * i.t + tn.y * i.b + tn.z * i.n);
#else
    float3 N = normalize(i.n);
#endif
    float3 V = normalize(u_EyePos - i.worldPos);
    float4 spec = tex2D(s_Spec, i.uv);
    float3 diff = 0, specAcc = 0;
    float sh = ShadowTerm(i.shadowUV);
    [unroll]
    for (int k = 0; k < NUM_LIGHTS; k++)
    {
        float3 L = u_LightPos[k].xyz - i.worldPos * u_LightPos[k].w;
        float att = 1 / (1 + dot(L, L) * u_LightCol[k].w);
        L = normalize(L);
        float ndl = saturate(dot(N, L)) * att * (k == 0 ? sh : 1);
        diff += u_LightCol[k].rgb * ndl;
        specAcc += u_LightCol[k].rgb * pow(saturate(dot(N, normalize(L + V))), u_Gloss) * ndl;
    }
    float3 c = albedo.rgb * diff + spec.rgb * specAcc;
#if HAS_EMISSIVE
    c += tex2D(s_Emissive, i.uv).rgb * u_EmissiveScale;
#endif
#if HAS_FOG
    float f = exp(-length(u_EyePos - i.worldPos) * u_FogColorDensity.w);
    c = lerp(u_FogColorDensity.rgb, c, f);
#endif
    return float4(c, albedo.a);
}
