// A fully unrolled 200-iteration loop: well over 512 instruction slots. D3DCompile does not
// refuse it (the 512 limit is a device cap checked when the shader is created).
float4 coeff[4];

float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 x = v;
    [unroll]
    for (int i = 0; i < 200; i++)
        x = frac(x * coeff[i % 4] + coeff[(i + 1) % 4].wzyx) * sin(x + i);
    return x;
}
