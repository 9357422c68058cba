// Shield bubble: hex pattern, intersection glow with scene depth, hit ripples from an array.
sampler2D hexTex : register(s0);
sampler2D depthMap : register(s1);
float4 hits[4];        // xyz position, w age
float4 shieldColor;
float3 eyeW;

float4 main(float2 uv : TEXCOORD0, float3 P : TEXCOORD1, float3 N : TEXCOORD2, float4 sp : TEXCOORD3) : COLOR
{
    float rim = pow(1 - abs(dot(normalize(N), normalize(eyeW - P))), 3);
    float hex = tex2D(hexTex, uv * 8).r;
    float inter = 1 - saturate(abs(tex2Dproj(depthMap, sp).r - sp.z / sp.w) * 200);
    float ripple = 0;
    [unroll] for (int i = 0; i < 4; i++)
    {
        float d = distance(P, hits[i].xyz);
        ripple += saturate(1 - abs(d - hits[i].w * 3)) * saturate(1 - hits[i].w);
    }
    return shieldColor * (rim + inter + ripple * hex + hex * 0.05);
}
