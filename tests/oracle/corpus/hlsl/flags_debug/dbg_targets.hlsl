// oracle: flags=DEBUG|SKIP_OPTIMIZATION
// Debug information for four render targets and a depth output, with a matrix local.
float4x4 xf;
struct Out { float4 c0 : COLOR0; float4 c1 : COLOR1; float4 c2 : COLOR2; float4 c3 : COLOR3; float d : DEPTH; };
Out main(float4 p : TEXCOORD0, float3 t : TEXCOORD1)
{
    Out o;
    float4 q = mul(p, xf);
    float3x3 m = float3x3(t, t.yzx, t.zxy);
    o.c0 = q;
    o.c1 = float4(mul(t, m), 0);
    o.c2 = q.wzyx;
    o.c3 = float4(t, q.x);
    o.d = q.z / q.w;
    return o;
}
