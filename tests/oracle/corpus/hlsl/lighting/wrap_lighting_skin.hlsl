// Wrap lighting for skin with a red-tinted scatter term.
sampler2D skinTex;
float3 L;
float wrap = 0.5;
float3 scatterTint = float3(0.8, 0.25, 0.1);

float4 main(float2 uv : TEXCOORD0, float3 nrm : TEXCOORD1) : COLOR
{
    float3 n = normalize(nrm);
    float ndl = dot(n, L);
    float diffuseWrap = saturate((ndl + wrap) / (1 + wrap));
    float scatter = smoothstep(0.0, wrap, diffuseWrap) * smoothstep(wrap * 2, wrap, diffuseWrap);
    float3 col = tex2D(skinTex, uv).rgb;
    return float4(col * (diffuseWrap + scatter * scatterTint), 1);
}
