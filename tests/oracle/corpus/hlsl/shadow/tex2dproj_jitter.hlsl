// Four projected lookups with offsets added in projective space.
sampler2D smap;
float2 jitter[4];
float  spread;

float4 main(float4 sc : TEXCOORD0) : COLOR
{
    float s = 0;
    [unroll] for (int i = 0; i < 4; i++)
        s += tex2Dproj(smap, sc + float4(jitter[i] * spread * sc.w, 0, 0)).r;
    return s * 0.25;
}
