// Glass: refract() per channel for a cheap dispersion look.
samplerCUBE envCube;
float3 camPos;
float3 etaRGB = float3(0.65, 0.67, 0.69);

half4 main(float3 P : TEXCOORD0, float3 N : TEXCOORD1) : COLOR
{
    float3 n = normalize(N);
    float3 i = normalize(P - camPos);
    half3 c;
    c.r = texCUBE(envCube, refract(i, n, etaRGB.r)).r;
    c.g = texCUBE(envCube, refract(i, n, etaRGB.g)).g;
    c.b = texCUBE(envCube, refract(i, n, etaRGB.b)).b;
    half3 refl = texCUBE(envCube, reflect(i, n)).rgb;
    half f = saturate(pow(1 + dot(i, n), 3));
    return half4(lerp(c, refl, f), 1);
}
