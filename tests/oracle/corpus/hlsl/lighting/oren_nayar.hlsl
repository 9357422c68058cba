// Oren-Nayar rough diffuse.
float3 lightDir;
float3 viewDir;
float sigma2 = 0.25;
float4 diffuseColor;

float4 main(float3 n : TEXCOORD0) : COLOR
{
    float3 N = normalize(n);
    float NdotL = dot(N, lightDir);
    float NdotV = dot(N, viewDir);
    float A = 1 - 0.5 * sigma2 / (sigma2 + 0.33);
    float B = 0.45 * sigma2 / (sigma2 + 0.09);
    float thetaI = acos(NdotL);
    float thetaR = acos(NdotV);
    float alpha = max(thetaI, thetaR);
    float beta = min(thetaI, thetaR);
    float gamma = dot(viewDir - N * NdotV, lightDir - N * NdotL);
    float od = max(0, NdotL) * (A + B * max(0, gamma) * sin(alpha) * tan(beta));
    return diffuseColor * od;
}
