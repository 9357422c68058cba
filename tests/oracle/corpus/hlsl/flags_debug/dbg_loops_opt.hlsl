// oracle: flags=DEBUG
// Debug information with optimisation on: an unrolled loop over an array.
float4 weights[4];
sampler2D tex : register(s0);
float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 sum = 0;
    for (int k = 0; k < 4; k++)
    {
        float2 o = uv + weights[k].xy;
        sum += tex2D(tex, o) * weights[k].w;
    }
    return sum;
}
