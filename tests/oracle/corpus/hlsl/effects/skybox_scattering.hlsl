// Sky: cheap Rayleigh/Mie approximation with a sun disc, stars from a cube map at night.
samplerCUBE stars;
float3 sunDirection;
float3 rayleighColor = float3(0.26, 0.41, 0.58);
float  mieG = 0.76;
float  nightAmount;

float4 main(float3 dir : TEXCOORD0) : COLOR
{
    float3 d = normalize(dir);
    float mu = dot(d, sunDirection);
    float rayleigh = 0.75 * (1 + mu * mu);
    float g2 = mieG * mieG;
    float mie = 1.5 * ((1 - g2) / (2 + g2)) * (1 + mu * mu) / pow(1 + g2 - 2 * mieG * mu, 1.5);
    float horizon = pow(1 - saturate(d.y), 4);
    float3 sky = rayleighColor * rayleigh * (1 + horizon) + mie * 0.02;
    float disc = smoothstep(0.9995, 0.9998, mu) * 20;
    float3 night = texCUBE(stars, d).rgb * nightAmount;
    return float4(sky * (1 - nightAmount) + disc + night, 1);
}
