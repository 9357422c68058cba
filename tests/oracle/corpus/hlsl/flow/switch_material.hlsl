// switch on an int material id coming from the vertex stream (abs() makes it known
// non-negative, which a ps_3_0 switch needs).
sampler2D t0 : register(s0);
sampler2D t1 : register(s1);
float4 tints[4];

float4 main(float2 uv : TEXCOORD0, float id : TEXCOORD1) : COLOR
{
    int m = (int)abs(id);
    float4 c;
    switch (m)
    {
        case 0: c = tex2D(t0, uv); break;
        case 1: c = tex2D(t1, uv); break;
        case 2: c = tex2D(t0, uv) * tex2D(t1, uv); break;
        default: c = tints[min(m, 3)]; break;
    }
    return c;
}
