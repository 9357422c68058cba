// Horizontal pass of a separable 9-tap Gaussian, weights and offsets from static arrays.
sampler2D inputTex : register(s0);
float texelWidth;

static const float weights[5] = { 0.2270270270, 0.1945945946, 0.1216216216, 0.0540540541, 0.0162162162 };

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 c = tex2D(inputTex, uv) * weights[0];
    [unroll]
    for (int i = 1; i < 5; ++i)
    {
        float2 o = float2(texelWidth * i, 0);
        c += tex2D(inputTex, uv + o) * weights[i];
        c += tex2D(inputTex, uv - o) * weights[i];
    }
    return c;
}
