// oracle: flags=DEBUG|SKIP_OPTIMIZATION
// Debug information through helper functions inlined into main, with their own locals.
float4 scale;
float3 shade(float3 n, float3 l)
{
    float d = saturate(dot(n, l));
    return d * scale.xyz;
}
float fade(float x)
{
    float y = x * x;
    return y * (3 - 2 * y);
}
float4 main(float3 n : TEXCOORD0, float3 l : TEXCOORD1) : COLOR
{
    float3 c = shade(normalize(n), l);
    float f = fade(c.y);
    return float4(c * f, f);
}
