// Helper functions called many times (all inlined by the compiler).
float4 p0, p1, p2;

float Hash(float2 p) { return frac(sin(dot(p, float2(12.9898, 78.233))) * 43758.5453); }
float Noise(float2 p)
{
    float2 i = floor(p), f = frac(p);
    float2 u = f * f * (3 - 2 * f);
    return lerp(lerp(Hash(i), Hash(i + float2(1, 0)), u.x),
                lerp(Hash(i + float2(0, 1)), Hash(i + 1), u.x), u.y);
}
float Fbm(float2 p)
{
    float v = 0, a = 0.5;
    [unroll] for (int o = 0; o < 4; o++) { v += a * Noise(p); p *= 2.03; a *= 0.5; }
    return v;
}

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float n = Fbm(uv * p0.xy + p0.zw);
    return lerp(p1, p2, n);
}
