// 3x3 box filter, nested unrolled loops.
sampler2D image;
float2 pixelSize;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 sum = 0;
    [unroll] for (int j = -1; j <= 1; j++)
        [unroll] for (int i = -1; i <= 1; i++)
            sum += tex2D(image, uv + float2(i, j) * pixelSize);
    return sum / 9;
}
