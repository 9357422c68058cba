// Night vision: luminance boost, green tint, noise, circular mask.
sampler2D screen : register(s0);
sampler2D noise : register(s1);
float  gain = 4;
float2 noiseOffset;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float l = dot(tex2D(screen, uv).rgb, float3(0.3, 0.59, 0.11)) * gain;
    float n = tex2D(noise, uv * 3 + noiseOffset).r;
    float2 c = uv - 0.5;
    float mask = 1 - smoothstep(0.4, 0.5, length(c * float2(1.6, 1)));
    return float4(float3(0.1, 0.95, 0.2) * (l + n * 0.2) * mask, 1);
}
