// oracle: target=vs_3_0
// vs_3_0 shader decompiled by ps30
float3 eye : register(c6);
float fadeDistance : register(c7);
float3 right : register(c4);
float3 up : register(c5);
float4x4 viewProj : register(c0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
    float4 texcoord0 : TEXCOORD0;
    float4 color0 : COLOR0;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, float4 color0 : COLOR0)
{
    precise float4 o0 = 0, o1 = 0, o2 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = texcoord2.y;
    r1.xy = float2(cos(r0.x), sin(r0.x));
    r0.xyz = r1.yyx * texcoord1.yxy;
    r1.x = texcoord1.x * r1.x - r0.x;
    r1.y = r0.z + r0.y;
    r0.xy = r1.xy * texcoord2.x;
    r0.xzw = right * r0.x + position0.xyz;
    r0.xyz = up * r0.y + r0.xzw;
    r0.w = 1.0;
    o0 = mul(r0, viewProj);
    r0.xyz = r0.xyz - eye;
    r0.x = dot(r0.xyz, r0.xyz);
    r0.x = 1.0 / rsqrt(abs(r0.x));
    o1.xy = texcoord1.xy * 0.5 + 0.5;
    r0.y = 1.0 / fadeDistance;
    o2 = saturate(r0.x * -r0.y + 1.0) * color0;
    VS_OUTPUT result;
    result.position0 = o0;
    result.texcoord0 = o1;
    result.color0 = o2;
    return result;
}
