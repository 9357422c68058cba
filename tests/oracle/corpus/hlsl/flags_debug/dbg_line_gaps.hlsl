// oracle: flags=DEBUG|SKIP_OPTIMIZATION
// Debug information when source lines advance and go back by 1 to 4.
float4 k;
float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 a = v * k;
    float4 b = a + k;

    float4 c = b * a;


    float4 d = c + b;



    float4 e = d * c;
    float4 f = e + d;
    float4 g = f * e;
    float4 h = g + f;
    float4 i = h * g;
    float4 j = i + h;
    float4 m = j * i;
    float4 n = m + j;
    return n;
}
