// oracle: target=vs_2_0
// A static mesh: world-view-projection transform, a world-space normal for per-pixel
// lighting, a texture-coordinate transform and linear fog.
float4x4 worldViewProj;
float4x3 world;
float4x4 texTransform;
float2 fogRange;

struct Out
{
    float4 pos : POSITION;
    float2 uv : TEXCOORD0;
    float3 normal : TEXCOORD1;
    float fog : FOG;
};

Out main(float4 pos : POSITION, float3 normal : NORMAL, float2 uv : TEXCOORD0)
{
    Out o;
    o.pos = mul(pos, worldViewProj);
    o.normal = mul(normal, (float3x3)world);
    o.uv = mul(float4(uv, 1, 0), texTransform).xy;
    o.fog = saturate((fogRange.y - o.pos.z) / (fogRange.y - fogRange.x));
    return o;
}
