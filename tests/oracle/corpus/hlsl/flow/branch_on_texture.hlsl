// Dynamic branch on a texture value, sampling in the branch with tex2Dlod.
sampler2D maskS : register(s0);
sampler2D expensive : register(s1);
float4 fallback;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float m = tex2D(maskS, uv).r;
    [branch]
    if (m > 0.5)
    {
        float4 s = 0;
        [unroll] for (int i = 0; i < 4; i++)
            s += tex2Dlod(expensive, float4(uv + i * 0.01, 0, i));
        return s * 0.25;
    }
    return fallback;
}
