// oracle: target=ps_2_a
// ps_2_a: a choice the compiler writes with setp and predicated instructions, gradients for
// an explicit texture LOD, and a dependent read chain longer than ps_2_0 allows.
sampler2D a : register(s0);
sampler2D b : register(s1);
float threshold;

float4 main(float2 uv : TEXCOORD0, float4 col : COLOR0) : COLOR
{
    float2 dx = ddx(uv) * 2;
    float2 dy = ddy(uv) * 2;
    float4 t = tex2Dgrad(a, uv, dx, dy);
    float4 u = tex2D(b, t.xy);
    float4 w = tex2D(a, u.zw);
    float4 v = tex2D(b, w.xy + u.xy);
    float4 r = v;
    if (t.x > threshold) r = v * col;
    if (t.y < threshold) r.w = t.w;
    return r;
}
