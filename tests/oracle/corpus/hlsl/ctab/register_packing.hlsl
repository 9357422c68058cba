// Many small uniforms; the compiler gives each its own register.
float a1, a2, a3, a4;
float2 b1, b2;
float3 c1;
float4 d1;
float4x2 m42;
float2x4 m24;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 r = v * a1 + a2 * a3 - a4;
    r.xy += b1 * b2;
    r.xyz *= c1;
    r += d1;
    r.xy += mul(v, m42);
    r += mul(v.xy, m24);
    return r;
}
