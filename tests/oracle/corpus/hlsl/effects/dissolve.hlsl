// Dissolve: clip by a noise texture against a threshold, glowing burn edge.
sampler2D albedo : register(s0);
sampler2D noiseMap : register(s1);
float  dissolveAmount;
float  edgeWidth = 0.05;
float3 edgeColor = float3(4, 1.5, 0.2);

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float n = tex2D(noiseMap, uv).r;
    float d = n - dissolveAmount;
    clip(d);
    float edge = 1 - smoothstep(0, edgeWidth, d);
    float4 c = tex2D(albedo, uv);
    c.rgb = lerp(c.rgb, edgeColor, edge);
    return c;
}
