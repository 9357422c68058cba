// An array of samplers indexed by constants (unrolled loop).
sampler2D layers[4];
float4 weights;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 c = 0;
    [unroll] for (int i = 0; i < 4; i++)
        c += tex2D(layers[i], uv) * weights[i];
    return c;
}
