// Two nested dynamic loops (loop inside loop) with int bounds.
int outerCount, innerCount;
float4 w;

float4 main(float4 p : TEXCOORD0) : COLOR
{
    float4 acc = 0;
    [loop] for (int i = 0; i < outerCount; i++)
        [loop] for (int j = 0; j < innerCount; j++)
            acc += sin(p * (i + 1) + j) * w;
    return acc;
}
