// Middle passes of the luminance chain: average 3x3 log-lum samples.
sampler2D lumTex;
float4 sampleOffsets[9];

float4 main(float2 t : TEXCOORD0) : COLOR0
{
    float acc = 0.0;
    for (int i = 0; i < 9; i++)
        acc += tex2D(lumTex, t + sampleOffsets[i].xy).r;
    return float4(acc / 9.0, 0, 0, 1);
}
