// Sobel edge detection on depth and normals for an outline effect.
sampler2D normalDepth;
float2 texel;
float4 edgeColor;
float threshold = 0.2;

static const float sx[9] = { -1, 0, 1, -2, 0, 2, -1, 0, 1 };
static const float sy[9] = { -1, -2, -1, 0, 0, 0, 1, 2, 1 };

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 gx = 0, gy = 0;
    [unroll]
    for (int i = 0; i < 9; i++)
    {
        float2 o = float2(i % 3 - 1, i / 3 - 1) * texel;
        float4 s = tex2D(normalDepth, uv + o);
        gx += s * sx[i];
        gy += s * sy[i];
    }
    float e = length(float2(length(gx), length(gy)));
    return edgeColor * step(threshold, e);
}
