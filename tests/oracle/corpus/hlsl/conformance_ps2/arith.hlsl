// oracle: target=ps_2_0
// ps_2_0 conformance: rsq, rcp, exp and log on uniform values whose results are powers of two.
float4 a : register(c0);

float4 main() : COLOR
{
    return float4(rsqrt(a.x), rcp(a.y), exp2(a.z), log2(a.w));
}
