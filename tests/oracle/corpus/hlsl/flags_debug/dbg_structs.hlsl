// oracle: flags=DEBUG|SKIP_OPTIMIZATION
// Debug information for a struct local, a struct input and two render targets.
struct PSIn { float2 uv : TEXCOORD0; float4 col : COLOR0; };
struct PSOut { float4 a : COLOR0; float4 b : COLOR1; };
sampler2D tex : register(s0);
struct Mat { float3 tint; float gain; };
PSOut main(PSIn i)
{
    Mat m;
    m.tint = i.col.rgb * 2;
    m.gain = i.col.a;
    PSOut o;
    o.a = tex2D(tex, i.uv) * float4(m.tint, 1);
    o.b = o.a * m.gain;
    return o;
}
