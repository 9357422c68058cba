// Depth-aware (bilateral) blur for half-resolution SSAO.
sampler2D aoTex    : register(s0);
sampler2D depthTex : register(s1);
float2 blurDir;
float  sharpness = 40;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float centerD = tex2D(depthTex, uv).r;
    float total = 0, wsum = 0;
    [unroll]
    for (int i = -4; i <= 4; i++)
    {
        float2 t = uv + blurDir * i;
        float d = tex2D(depthTex, t).r;
        float w = exp2(-i * i * 0.1 - abs(d - centerD) * sharpness);
        total += tex2D(aoTex, t).r * w;
        wsum += w;
    }
    return total / wsum;
}
