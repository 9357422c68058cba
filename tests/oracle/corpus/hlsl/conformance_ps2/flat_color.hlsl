// oracle: target=ps_2_0
// ps_2_0 conformance: the two colour inputs as two outputs, for flat shading (and their clamp
// to [0, 1]).
struct Out
{
    float4 c0 : COLOR0;
    float4 c1 : COLOR1;
};

Out main(float4 diffuse : COLOR0, float4 specular : COLOR1)
{
    Out o;
    o.c0 = diffuse;
    o.c1 = specular;
    return o;
}
