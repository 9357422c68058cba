// 9-tap tent upsample, added onto the higher mip.
sampler2D lowMip  : register(s0);
sampler2D highMip : register(s1);
float4 texel;     // xy size, z radius
float  blend;

static const float3 tent[9] =
{
    float3(-1, -1, 1), float3(0, -1, 2), float3(1, -1, 1),
    float3(-1,  0, 2), float3(0,  0, 4), float3(1,  0, 2),
    float3(-1,  1, 1), float3(0,  1, 2), float3(1,  1, 1),
};

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float3 s = 0;
    for (int i = 0; i < 9; i++)
        s += tex2D(lowMip, uv + tent[i].xy * texel.xy * texel.z).rgb * tent[i].z;
    s /= 16;
    return float4(tex2D(highMip, uv).rgb + s * blend, 1);
}
