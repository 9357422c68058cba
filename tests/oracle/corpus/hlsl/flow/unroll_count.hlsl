// [unroll(n)] with an explicit count on a loop whose bound is a uniform.
float4 vals[8];
int n;

float4 main(float4 x : TEXCOORD0) : COLOR
{
    float4 s = 0;
    [unroll(8)]
    for (int i = 0; i < n; i++)
        s += vals[i] * x;
    return s;
}
