// First pass of the average: log luminance of a 4x4 neighbourhood into one texel.
sampler2D src : register(s0);
float2 texelSize;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float sum = 0;
    [unroll] for (int y = 0; y < 4; y++)
    [unroll] for (int x = 0; x < 4; x++)
    {
        float2 o = (float2(x, y) - 1.5) * texelSize;
        float3 c = tex2D(src, uv + o).rgb;
        sum += log(dot(c, float3(0.2125, 0.7154, 0.0721)) + 0.0001);
    }
    return sum / 16;
}
