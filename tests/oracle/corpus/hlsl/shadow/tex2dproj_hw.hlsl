// Hardware shadow map (depth texture): tex2Dproj returns the filtered comparison.
sampler2D shadowSampler : register(s2);
sampler2D baseSampler   : register(s0);
float4 lightColor;
float4 ambient;

float4 main(float2 uv : TEXCOORD0, float4 shadowCoord : TEXCOORD1, float ndl : TEXCOORD2) : COLOR
{
    float shadow = tex2Dproj(shadowSampler, shadowCoord).r;
    return tex2D(baseSampler, uv) * (ambient + lightColor * saturate(ndl) * shadow);
}
