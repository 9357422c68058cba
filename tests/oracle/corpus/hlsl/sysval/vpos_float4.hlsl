// VPOS read as float4 (only xy are defined), with interleaved-gradient noise.
float4 main(float4 p : VPOS) : COLOR
{
    float n = frac(52.9829189 * frac(dot(p.xy, float2(0.06711056, 0.00583715))));
    return float4(n, n, n, 1);
}
