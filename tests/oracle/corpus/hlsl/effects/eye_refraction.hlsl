// Eye: parallax-refracted iris under a cornea bulge, with a wet specular.
sampler2D irisTex;
sampler2D scleraTex;
float irisRadius = 0.2;
float irisDepth = 0.05;
float3 lightT;

float4 main(float2 uv : TEXCOORD0, float3 viewT : TEXCOORD1) : COLOR
{
    float2 c = uv - 0.5;
    float r = length(c);
    float inIris = smoothstep(irisRadius + 0.01, irisRadius - 0.01, r);
    float3 v = normalize(viewT);
    float h = irisDepth * (1 - r * r / (irisRadius * irisRadius));
    float2 ruv = uv - v.xy / v.z * h * inIris;
    float4 col = lerp(tex2D(scleraTex, uv), tex2D(irisTex, (ruv - 0.5) / (2 * irisRadius) + 0.5), inIris);
    float3 n = normalize(float3(c * 2, 1));
    float spec = pow(saturate(dot(reflect(-normalize(lightT), n), v)), 200);
    return col + spec;
}
