// oracle: target=ps_2_0 flags=SKIP_OPTIMIZATION
// ps_2_0 conformance: constants set by the application that are not finite numbers, through
// rcp twice (kept apart by compiling without optimisation) and a product.
float4 k : register(c0);

float4 main() : COLOR
{
    float4 r;
    r.x = rcp(rcp(k.x));
    r.y = rcp(rcp(k.y));
    r.z = k.z * k.w;
    r.w = rcp(k.w);
    return r;
}
