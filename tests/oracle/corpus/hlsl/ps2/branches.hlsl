// oracle: target=ps_2_a
// ps_2_a flow control: a bool uniform's static branch and a branch on a texture
// value, which the compiler flattens (it unrolls loops for ps_2_a, X3511 on an int count, and
// refuses [branch], X3528).
sampler2D tex : register(s0);
bool useTint;
float4 tint;
float2 step;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 t = tex2D(tex, uv);
    float4 sum = t * step.x + t.wzyx * step.y;
    if (sum.w > 1)
        sum /= sum.w;
    if (useTint)
        sum *= tint;
    return sum;
}
