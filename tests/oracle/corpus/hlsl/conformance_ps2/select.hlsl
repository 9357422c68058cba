// oracle: target=ps_2_0
// ps_2_0 conformance: a per-pixel choice without branches (cmp) and dp2add-style dot products.
float4 k : register(c0);

float4 main(float4 t : TEXCOORD0, float4 c : COLOR0) : COLOR
{
    float4 r;
    r.x = t.x > 0.5 ? k.x : k.y;
    r.y = dot(t.xy, k.zw);
    r.z = c.x * 4;
    r.w = lerp(k.x, k.y, t.x);
    return r;
}
