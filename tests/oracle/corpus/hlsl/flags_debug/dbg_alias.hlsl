// oracle: flags=DEBUG|SKIP_OPTIMIZATION
// Debug information where one instruction may serve several variables: copies and out parameters.
float4 k;
void split(float4 v, out float2 lo, out float2 hi)
{
    lo = v.xy;
    hi = v.zw;
}
float4 main(float4 v : TEXCOORD0) : COLOR
{
    float2 a, b;
    split(v * k, a, b);
    float2 c = a;
    float2 d = c;
    return float4(d, b);
}
