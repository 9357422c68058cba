// Parallax occlusion mapping: linear search with break, then a secant refinement.
// Gradients are taken outside the loop and passed to tex2Dgrad.
sampler2D HeightSampler : register(s0);
sampler2D AlbedoSampler : register(s1);
float HeightScale = 0.05;
int   MinSamples = 8;
int   MaxSamples = 32;

float4 main(float2 uv : TEXCOORD0, float3 viewTS : TEXCOORD1, float3 normalTS : TEXCOORD2) : COLOR
{
    float3 V = normalize(viewTS);
    float2 dx = ddx(uv), dy = ddy(uv);
    int n = (int)lerp(MaxSamples, MinSamples, abs(dot(V, normalize(normalTS))));
    float stepSize = 1.0 / n;
    float2 delta = -V.xy / V.z * HeightScale * stepSize;

    float currH = 1.0, prevH = 1.0, rayH = 1.0;
    float2 cur = uv, prev = uv;
    [loop]
    for (int i = 0; i < n; i++)
    {
        currH = tex2Dgrad(HeightSampler, cur, dx, dy).r;
        if (currH > rayH)
            break;
        prev = cur; prevH = currH;
        cur += delta;
        rayH -= stepSize;
    }
    float after = currH - rayH;
    float before = prevH - rayH - stepSize;
    float w = after / (after - before);
    float2 hit = lerp(cur, prev, w);
    return tex2Dgrad(AlbedoSampler, hit, dx, dy);
}
