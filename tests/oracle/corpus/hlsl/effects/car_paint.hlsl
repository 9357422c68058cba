// Two-layer car paint: colour shift by view angle, metallic flakes, clear coat reflection.
sampler2D flakeNormals : register(s0);
samplerCUBE envMap : register(s1);
float4 paintColorMid, paintColorEdge;
float flakeScale = 20;
float3 eyePos;

float4 main(float2 uv : TEXCOORD0, float3 P : TEXCOORD1, float3 N : TEXCOORD2) : COLOR
{
    float3 n = normalize(N);
    float3 v = normalize(eyePos - P);
    float ndv = saturate(dot(n, v));
    float3 flake = tex2D(flakeNormals, uv * flakeScale).xyz * 2 - 1;
    float3 fn = normalize(n + flake * 0.2);
    float sparkle = pow(saturate(dot(fn, v)), 32);
    float4 base = lerp(paintColorEdge, paintColorMid, ndv * ndv);
    float fres = 0.04 + 0.96 * pow(1 - ndv, 5);
    float3 refl = texCUBE(envMap, reflect(-v, n)).rgb;
    return float4(base.rgb + sparkle * 0.5 + refl * fres, 1);
}
