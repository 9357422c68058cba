// Relief mapping: linear search then a binary search, both with explicit LOD.
sampler2D reliefMap;
sampler2D texmap;
float depth;
float lodBias;

float2 Intersect(float2 dp, float2 ds)
{
    const int LINEAR = 10, BINARY = 5;
    float size = 1.0 / LINEAR;
    float d = 0.0, best = 1.0;
    [loop]
    for (int i = 0; i < LINEAR - 1; i++)
    {
        d += size;
        float4 t = tex2Dlod(reliefMap, float4(dp + ds * d, 0, lodBias));
        if (best > 0.996 && d >= t.w) best = d;
    }
    d = best;
    [loop]
    for (int j = 0; j < BINARY; j++)
    {
        size *= 0.5;
        float4 t = tex2Dlod(reliefMap, float4(dp + ds * d, 0, lodBias));
        if (d >= t.w) { best = d; d -= 2 * size; }
        d += size;
    }
    return dp + ds * best;
}

float4 main(float2 uv : TEXCOORD0, float3 view : TEXCOORD1) : COLOR
{
    float3 v = normalize(view);
    float2 ds = v.xy * depth / v.z;
    return tex2D(texmap, Intersect(uv, ds));
}
