// Tangent-space normal mapping with an interpolated TBN frame.
sampler2D ColorSampler  : register(s0);
sampler2D NormalSampler : register(s1);
float3 SunDirection;
float4 SunColor;
float4 Ambient;

struct VSOut
{
    float2 Tex      : TEXCOORD0;
    float3 Tangent  : TEXCOORD1;
    float3 Binormal : TEXCOORD2;
    float3 Normal   : TEXCOORD3;
};

float4 main(VSOut In) : COLOR0
{
    float3 tn = tex2D(NormalSampler, In.Tex).xyz * 2.0 - 1.0;
    float3x3 tbn = float3x3(normalize(In.Tangent), normalize(In.Binormal), normalize(In.Normal));
    float3 N = normalize(mul(tn, tbn));
    float4 c = tex2D(ColorSampler, In.Tex);
    return c * (Ambient + SunColor * saturate(dot(N, SunDirection)));
}
