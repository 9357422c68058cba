// oracle: target=ps_2_0
// Cube-map reflection blended over a base colour by a Fresnel term, and a volume-texture
// noise read that scales the result.
samplerCUBE envMap : register(s0);
sampler3D noise : register(s1);
float fresnelBias;
float fresnelScale;
float4 baseColor;

float4 main(float3 normal : TEXCOORD0, float3 view : TEXCOORD1, float3 pos : TEXCOORD2) : COLOR
{
    float3 n = normalize(normal);
    float3 v = normalize(view);
    float3 r = reflect(-v, n);
    float f = saturate(fresnelBias + fresnelScale * pow(1 - saturate(dot(n, v)), 5));
    float3 env = texCUBE(envMap, r).rgb;
    float grain = tex3D(noise, pos).r;
    return float4(lerp(baseColor.rgb, env, f) * (0.75 + 0.25 * grain), 1);
}
