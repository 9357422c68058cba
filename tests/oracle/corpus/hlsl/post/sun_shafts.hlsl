// Screen-space light shafts: march toward the sun, occlusion from a mask.
sampler2D occlusionMask;
float2 sunScreenPos;
float density = 0.9, weight = 0.05, decay = 0.96, exposure = 0.3;
#define NUM_SAMPLES 24

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float2 delta = (uv - sunScreenPos) * density / NUM_SAMPLES;
    float illum = 1, acc = 0;
    float2 t = uv;
    [unroll(NUM_SAMPLES)]
    for (int i = 0; i < NUM_SAMPLES; i++)
    {
        t -= delta;
        acc += tex2D(occlusionMask, t).r * illum * weight;
        illum *= decay;
    }
    return acc * exposure;
}
