// Snow on upward-facing surfaces, mask sharpened with smoothstep.
sampler2D baseTex, snowTex, normTex;
float snowAmount;
float3 upWS = float3(0, 1, 0);

float4 main(float2 uv : TEXCOORD0, float3 nWS : TEXCOORD1) : COLOR
{
    float3 n = normalize(nWS + (tex2D(normTex, uv).xyz - 0.5) * 0.3);
    float s = smoothstep(1 - snowAmount, 1 - snowAmount + 0.1, dot(n, upWS));
    return lerp(tex2D(baseTex, uv), tex2D(snowTex, uv * 3), s);
}
