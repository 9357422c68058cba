// Conformance corpus: three render targets written from one shader (oC0-oC2).
struct Out
{
    float4 c0 : COLOR0;
    float4 c1 : COLOR1;
    float4 c2 : COLOR2;
};

Out main(float4 t : TEXCOORD0)
{
    Out o;
    o.c0 = t;
    o.c1 = t * 0.5;
    o.c2 = t.wzyx;
    return o;
}
