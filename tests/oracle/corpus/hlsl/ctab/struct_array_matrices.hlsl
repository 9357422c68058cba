// Array of structs holding a matrix and vectors (projected decals).
struct Decal
{
    float4x4 worldToDecal;
    float4   tint;
    float2   fade;
};
Decal decals[3];
sampler2D decalAtlas;

float4 main(float4 wpos : TEXCOORD0) : COLOR
{
    float4 c = 0;
    [unroll] for (int i = 0; i < 3; i++)
    {
        float4 p = mul(wpos, decals[i].worldToDecal);
        float inside = all(abs(p.xyz) < 1);
        float4 s = tex2D(decalAtlas, p.xy * 0.5 + 0.5) * decals[i].tint;
        c = lerp(c, s, s.a * inside * saturate((1 - abs(p.z)) * decals[i].fade.x));
    }
    return c;
}
