// continue inside a loop skips masked samples.
float4 data[8];
float4 mask;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 s = 0;
    [loop]
    for (int i = 0; i < 8; i++)
    {
        if (data[i].w < mask.x)
            continue;
        s += data[i] * v;
    }
    return s;
}
