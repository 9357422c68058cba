// oracle: target=ps_2_0
// ps_2_0 conformance: four render targets written from one shader (oC0-oC3).
struct Out
{
    float4 c0 : COLOR0;
    float4 c1 : COLOR1;
    float4 c2 : COLOR2;
    float4 c3 : COLOR3;
};

Out main(float4 t : TEXCOORD0)
{
    Out o;
    o.c0 = t;
    o.c1 = t * 0.5;
    o.c2 = t.wzyx;
    o.c3 = t + 0.25;
    return o;
}
