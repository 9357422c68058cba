// Gaussian whose 13 weights and offsets are set by the application each frame.
#define TAPS 13
sampler2D Source : register(s0);
float4 SampleOffsetsWeights[TAPS] : register(c0);   // xy offset, z weight

float4 main(float2 uv : TEXCOORD0) : COLOR0
{
    float4 acc = 0;
    for (int i = 0; i < TAPS; i++)
        acc += SampleOffsetsWeights[i].z * tex2D(Source, uv + SampleOffsetsWeights[i].xy);
    return acc;
}
