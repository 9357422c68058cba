// G-buffer fill: albedo, view-space normal, depth and material params in four targets.
sampler2D DiffuseTex : register(s0);
sampler2D NormalTex  : register(s1);
sampler2D SpecTex    : register(s2);
float FarClip;

struct GBufferOut
{
    float4 Albedo   : COLOR0;
    float4 Normal   : COLOR1;
    float4 Depth    : COLOR2;
    float4 Material : COLOR3;
};

GBufferOut main(float2 uv : TEXCOORD0, float3 T : TEXCOORD1, float3 B : TEXCOORD2,
                float3 N : TEXCOORD3, float viewZ : TEXCOORD4)
{
    GBufferOut o;
    float3 tn = tex2D(NormalTex, uv).xyz * 2 - 1;
    float3 n = normalize(tn.x * T + tn.y * B + tn.z * N);
    o.Albedo   = tex2D(DiffuseTex, uv);
    o.Normal   = float4(n * 0.5 + 0.5, 0);
    o.Depth    = float4(viewZ / FarClip, 0, 0, 0);
    o.Material = tex2D(SpecTex, uv);
    return o;
}
