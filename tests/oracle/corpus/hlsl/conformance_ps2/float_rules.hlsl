// oracle: target=ps_2_0
// ps_2_0 conformance: products where hardware and IEEE arithmetic differ: 0 times infinity in
// a multiply, a multiply-add and a dot product.
float4 a : register(c0);
float4 b : register(c1);
float4 c : register(c2);

float4 main() : COLOR
{
    float4 r;
    r.x = a.x * b.x;
    r.y = a.x * b.x + c.x;
    r.z = dot(a.xyz, b.xyz);
    r.w = a.w * b.w + c.w;
    return r;
}
