// Conformance corpus: the diffuse and specular colour inputs as outputs, for flat shading.
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
