// Crytek-style SSAO: random rotation texture, 8 samples in a sphere, depth compare.
sampler2D DepthSampler  : register(s0);
sampler2D RandomSampler : register(s1);
float4 ScreenParams;     // xy = screen / noise size
float  SampleRadius = 0.02;
float  DepthScale = 100;

static const float3 Kernel[8] = {
    float3( 0.355512, -0.709318, -0.102371), float3( 0.534186,  0.71511,  -0.115167),
    float3(-0.87866,   0.157139, -0.115167), float3( 0.140679, -0.475516, -0.0639818),
    float3(-0.0796121, 0.158842, -0.677075), float3(-0.0759516,-0.101676, -0.483625),
    float3( 0.12493,  -0.0223423,-0.483625), float3(-0.0720074, 0.243395, -0.967251) };

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float z = tex2D(DepthSampler, uv).r;
    float3 rnd = tex2D(RandomSampler, uv * ScreenParams.xy).xyz * 2 - 1;
    float occ = 0;
    for (int i = 0; i < 8; i++)
    {
        float3 r = reflect(Kernel[i], rnd);
        float2 suv = uv + r.xy * SampleRadius / z;
        float sz = tex2D(DepthSampler, suv).r;
        float dz = (z - sz) * DepthScale;
        occ += step(0.02, dz) * (1 - smoothstep(0.5, 2, dz));
    }
    return 1 - occ / 8;
}
