// Per-pixel normals from a sum of three Gerstner waves.
float4 waves[3];      // xy direction, z steepness, w wavelength
float  t;
samplerCUBE sky;
float3 eyeW;

float4 main(float3 wp : TEXCOORD0) : COLOR
{
    float3 nrm = float3(0, 1, 0);
    [unroll] for (int i = 0; i < 3; i++)
    {
        float k = 6.2831853 / waves[i].w;
        float c = sqrt(9.8 / k);
        float2 d = normalize(waves[i].xy);
        float f = k * (dot(d, wp.xz) - c * t);
        float a = waves[i].z / k;
        nrm.xz -= d * (k * a * cos(f));
        nrm.y -= waves[i].z * sin(f);
    }
    nrm = normalize(nrm);
    float3 v = normalize(wp - eyeW);
    return texCUBE(sky, reflect(v, nrm));
}
