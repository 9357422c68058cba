// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float heightScale : register(c4);
float texel : register(c5);
float4x4 worldViewProj : register(c0);
sampler2D heightMap : register(s0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
    float4 color0 : COLOR0;
    float4 texcoord0 : TEXCOORD0;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 texcoord0 : TEXCOORD0)
{
    precise float4 o0 = 0, o1 = 0, o2 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = tex2Dlod(heightMap, (float4(1.0, 1.0, 0.0, 0.0) * texcoord0.xyxx));
    r1.y = r0.x * heightScale + position0.y;
    r1.xzw = position0.xzw;
    o0 = mul(r1, worldViewProj);
    r1 = float4(1.0, 0.0, 0.0, 0.0);
    r1.xy = texel * r1.xy + texcoord0.xy;
    r1.y = r0.x - (tex2Dlod(heightMap, r1).x);
    r0.zw = float2(1.0, 0.0) * texcoord0.x;
    r1.xz = texel;
    r0.y = r1.x + texcoord0.y;
    r1.w = r0.x - (tex2Dlod(heightMap, r0.zyww).x);
    o1.xyz = normalize(r1.yzw) * 0.5 + 0.5;
    o1.w = 1.0;
    o2.xy = texcoord0.xy;
    VS_OUTPUT result;
    result.position0 = o0;
    result.color0 = o1;
    result.texcoord0 = o2;
    return result;
}
