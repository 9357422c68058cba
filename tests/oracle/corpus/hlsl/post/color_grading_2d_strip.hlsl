// LUT stored as a 256x16 strip: two lookups blended on the blue slice.
sampler2D src : register(s0);
sampler2D lutStrip : register(s1);

float3 StripLookup(float3 c)
{
    const float N = 16;
    float b = c.b * (N - 1);
    float slice0 = floor(b);
    float slice1 = min(slice0 + 1, N - 1);
    float2 uv = float2((c.r * (N - 1) + 0.5) / (N * N), (c.g * (N - 1) + 0.5) / N);
    float3 a = tex2D(lutStrip, uv + float2(slice0 / N, 0)).rgb;
    float3 d = tex2D(lutStrip, uv + float2(slice1 / N, 0)).rgb;
    return lerp(a, d, b - slice0);
}

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 c = saturate(tex2D(src, uv));
    return float4(StripLookup(c.rgb), c.a);
}
