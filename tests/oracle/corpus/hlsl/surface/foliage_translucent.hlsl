// Two-sided foliage: VFACE flips the normal, back lighting through the leaf.
sampler2D leafTex;
float3 sunDir;
float3 sunCol;
float  translucency = 0.6;
float  cutoff = 0.35;

float4 main(float2 uv : TEXCOORD0, float3 n : TEXCOORD1, float face : VFACE) : COLOR
{
    float4 c = tex2D(leafTex, uv);
    clip(c.a - cutoff);
    float3 N = normalize(n) * (face > 0 ? 1 : -1);
    float front = saturate(dot(N, sunDir));
    float back = saturate(dot(-N, sunDir)) * translucency;
    return float4(c.rgb * sunCol * (front + back + 0.2), 1);
}
