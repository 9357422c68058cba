// Arrays of bool and int uniforms.
bool  lightOn[4];
int   sampleCount[2];
float4 lightCol[4];

float4 main(float4 n : TEXCOORD0) : COLOR
{
    float4 c = 0;
    [unroll] for (int i = 0; i < 4; i++)
        if (lightOn[i]) c += lightCol[i] * n;
    for (int k = 0; k < sampleCount[1]; k++)
        c *= 0.9;
    return c;
}
