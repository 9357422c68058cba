// Second-order spherical-harmonic irradiance, nine coefficients per channel.
float4 cAr, cAg, cAb;   // l=0,1 terms
float4 cBr, cBg, cBb;   // l=2 quadratic terms
float4 cC;              // final quadratic

float3 ShadeSH9(float4 n)
{
    float3 x1, x2, x3;
    x1.r = dot(cAr, n); x1.g = dot(cAg, n); x1.b = dot(cAb, n);
    float4 vB = n.xyzz * n.yzzx;
    x2.r = dot(cBr, vB); x2.g = dot(cBg, vB); x2.b = dot(cBb, vB);
    float vC = n.x * n.x - n.y * n.y;
    x3 = cC.rgb * vC;
    return x1 + x2 + x3;
}

float4 main(float3 normal : TEXCOORD0, float4 albedo : COLOR0) : COLOR
{
    float4 n = float4(normalize(normal), 1);
    return float4(albedo.rgb * ShadeSH9(n), albedo.a);
}
