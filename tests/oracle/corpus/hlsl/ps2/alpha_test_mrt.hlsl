// oracle: target=ps_2_0
// A G-buffer pass for alpha-tested foliage: clip on the texture's alpha, then albedo, a
// packed normal and a depth to three render targets.
sampler2D leaves : register(s0);
float alphaRef;
float farPlane;

struct Out
{
    float4 albedo : COLOR0;
    float4 normal : COLOR1;
    float4 depth : COLOR2;
};

Out main(float2 uv : TEXCOORD0, float3 normal : TEXCOORD1, float viewZ : TEXCOORD2)
{
    float4 t = tex2D(leaves, uv);
    clip(t.a - alphaRef);
    Out o;
    o.albedo = t;
    o.normal = float4(normalize(normal) * 0.5 + 0.5, 1);
    o.depth = viewZ / farPlane;
    return o;
}
