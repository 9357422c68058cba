// PCSS: blocker search, penumbra estimate, then filtering; loops kept as loops
// with explicit-LOD fetches.
sampler2D shadowDepth;
float lightSizeUV;
float nearPlane;
static const float2 taps[8] = {
    float2(-0.7071, 0.7071), float2(0, -0.875), float2(0.5303, 0.5303), float2(-0.625, 0),
    float2(0.3536, -0.3536), float2(0, 0.375), float2(-0.1768, -0.1768), float2(0.125, 0) };

float4 main(float4 sc : TEXCOORD0) : COLOR
{
    float3 p = sc.xyz / sc.w;
    float searchW = lightSizeUV * (p.z - nearPlane) / p.z;
    float blockerSum = 0, numBlockers = 0;
    [loop] for (int i = 0; i < 8; i++)
    {
        float d = tex2Dlod(shadowDepth, float4(p.xy + taps[i] * searchW, 0, 0)).r;
        if (d < p.z) { blockerSum += d; numBlockers++; }
    }
    if (numBlockers == 0) return 1;
    float avgBlocker = blockerSum / numBlockers;
    float penumbra = (p.z - avgBlocker) * lightSizeUV * nearPlane / (avgBlocker * p.z);
    float lit = 0;
    [loop] for (int k = 0; k < 8; k++)
        lit += tex2Dlod(shadowDepth, float4(p.xy + taps[k] * penumbra, 0, 0)).r >= p.z;
    return lit / 8;
}
