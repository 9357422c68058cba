// Conformance corpus: a shader that reads forty constants and a texture, run from an inputs
// file rather than forty --const flags.
float4 weights[40] : register(c0);
sampler2D image : register(s0);

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 sum = 0;
    [unroll] for (int i = 0; i < 40; i++)
        sum += weights[i];
    return sum * tex2D(image, uv);
}
