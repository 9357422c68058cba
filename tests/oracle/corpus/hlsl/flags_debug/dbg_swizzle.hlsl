// oracle: flags=DEBUG|SKIP_OPTIMIZATION
// Debug information for variables held in shuffled register components.
float4 k;
float4 main(float4 v : TEXCOORD0, float2 t : TEXCOORD1) : COLOR
{
    float2 s = t.yx * k.zw;
    float3 q = v.zxy + s.yxy;
    float4 r;
    r.zw = s;
    r.xy = q.yz;
    return r;
}
