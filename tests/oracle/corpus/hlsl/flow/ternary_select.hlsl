// Ternaries everywhere: cmp-style selects on vectors.
float4 lo, hi;

float4 main(float4 a : TEXCOORD0, float4 b : TEXCOORD1) : COLOR
{
    float4 m = a > b ? a : b;
    float4 s = a.x < 0 ? lo : hi;
    float4 z = (a == b) ? 1 : 0;
    return m + s + z + (b != 0 ? 1 / b : 0);
}
