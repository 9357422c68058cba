// Lava: flow-map distortion with two phases, emissive boosted by a noise.
sampler2D flowMap : register(s0);
sampler2D lavaTex : register(s1);
float time;
float flowSpeed = 0.2;
float emissive = 3;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float2 flow = tex2D(flowMap, uv).rg * 2 - 1;
    float p0 = frac(time * flowSpeed);
    float p1 = frac(time * flowSpeed + 0.5);
    float4 a = tex2D(lavaTex, uv + flow * p0);
    float4 b = tex2D(lavaTex, uv + flow * p1);
    float w = abs((0.5 - p0) / 0.5);
    float4 c = lerp(a, b, w);
    return c * (1 + emissive * c.a);
}
