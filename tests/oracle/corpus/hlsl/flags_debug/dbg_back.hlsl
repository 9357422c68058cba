// oracle: flags=DEBUG|SKIP_OPTIMIZATION
// Debug information when source lines go back by 2, 3 and 4 through #line.
float4 k;
float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 a = v * k;
#line 4
    float4 b = a + k;
#line 2
    float4 c = b * a;
#line 20
    float4 d = c + b;
#line 17
    float4 e = d * c;
#line 15
    float4 f = e + d;
#line 12
    float4 g = f * e;
    return g;
}
