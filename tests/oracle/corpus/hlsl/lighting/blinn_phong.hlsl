// Blinn-Phong with a gloss map in the specular alpha channel.
sampler2D g_Diffuse  : register(s0);
sampler2D g_Specular : register(s1);

float3 g_LightDir   : register(c0);
float4 g_LightColor : register(c1);
float3 g_EyePos     : register(c2);
float  g_SpecPower  : register(c3) = 32.0;

float4 main(float2 tc : TEXCOORD0,
            float3 N  : TEXCOORD1,
            float3 P  : TEXCOORD2) : COLOR0
{
    float3 n = normalize(N);
    float3 v = normalize(g_EyePos - P);
    float3 h = normalize(g_LightDir + v);

    float  diff = max(dot(n, g_LightDir), 0);
    float4 spec = tex2D(g_Specular, tc);
    float  s    = pow(saturate(dot(n, h)), g_SpecPower * spec.a);

    float3 c = tex2D(g_Diffuse, tc).rgb * diff + spec.rgb * s;
    return float4(c * g_LightColor.rgb, 1);
}
