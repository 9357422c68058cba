// oracle: target=vs_3_0
// vs_3_0: terrain displaced by a height map read with tex2Dlod (texldl), its normal from
// two more reads, and a colour output.
sampler2D heightMap : register(s0);
float4x4 worldViewProj;
float heightScale;
float texel;

struct Out
{
    float4 pos : POSITION;
    float4 color : COLOR0;
    float2 uv : TEXCOORD0;
};

Out main(float4 pos : POSITION, float2 uv : TEXCOORD0)
{
    float h = tex2Dlod(heightMap, float4(uv, 0, 0)).r;
    float hx = tex2Dlod(heightMap, float4(uv + float2(texel, 0), 0, 0)).r;
    float hy = tex2Dlod(heightMap, float4(uv + float2(0, texel), 0, 0)).r;
    float4 p = pos;
    p.y += h * heightScale;
    Out o;
    o.pos = mul(p, worldViewProj);
    o.color = float4(normalize(float3(h - hx, texel, h - hy)) * 0.5 + 0.5, 1);
    o.uv = uv;
    return o;
}
