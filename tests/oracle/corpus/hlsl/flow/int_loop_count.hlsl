// int uniform as loop bound: rep/loop with an integer constant register.
int  iterations : register(i0);
float4 step4;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 acc = v;
    for (int i = 0; i < iterations; i++)
        acc = acc * 0.5 + step4;
    return acc;
}
