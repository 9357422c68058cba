// Box blur of variable radius (int uniform), dynamic loop.
sampler2D s0 : register(s0);
float2 step_uv;
int radius;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 acc = 0;
    float n = 0;
    [loop]
    for (int i = -radius; i <= radius; i++)
    {
        acc += tex2Dlod(s0, float4(uv + step_uv * i, 0, 0));
        n += 1;
    }
    return acc / n;
}
