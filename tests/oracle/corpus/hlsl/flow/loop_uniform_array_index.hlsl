// Loop counter indexes a uniform array: relative addressing through aL.
float4 coeffs[12];
int count;

float4 main(float4 x : TEXCOORD0) : COLOR
{
    float4 r = 0;
    [loop]
    for (int i = 0; i < count; i++)
        r += coeffs[i] * x;
    return r;
}
