// do/while with a counter, a shape some older code bases use.
float4 seed;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 x = v;
    int n = 0;
    [loop]
    do
    {
        x = frac(x * 1.618 + seed);
        n++;
    } while (x.x > 0.1 && n < 10);
    return x;
}
