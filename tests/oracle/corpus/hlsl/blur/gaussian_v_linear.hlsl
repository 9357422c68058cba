// Vertical Gaussian using linear-filtering taps (5 fetches for 9 texels).
sampler2D blurSrc;
float2 invSize;
static const float offs[3] = { 0.0, 1.3846153846, 3.2307692308 };
static const float wts[3]  = { 0.2270270270, 0.3162162162, 0.0702702703 };

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 r = tex2D(blurSrc, uv) * wts[0];
    for (int i = 1; i < 3; i++)
    {
        r += tex2D(blurSrc, uv + float2(0, offs[i] * invSize.y)) * wts[i];
        r += tex2D(blurSrc, uv - float2(0, offs[i] * invSize.y)) * wts[i];
    }
    return r;
}
