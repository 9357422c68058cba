// 3x3 percentage-closer filtering on an R32F shadow map.
sampler2D ShadowMap : register(s1);
sampler2D Diffuse   : register(s0);
float  ShadowMapSize = 1024;
float  DepthBias = 0.0015;
float3 LightDir;

float4 main(float2 uv : TEXCOORD0, float4 lightPos : TEXCOORD1, float3 N : TEXCOORD2) : COLOR
{
    float2 suv = lightPos.xy / lightPos.w * float2(0.5, -0.5) + 0.5;
    float depth = lightPos.z / lightPos.w - DepthBias;
    float texel = 1.0 / ShadowMapSize;
    float lit = 0;
    for (int y = -1; y <= 1; y++)
        for (int x = -1; x <= 1; x++)
            lit += depth <= tex2D(ShadowMap, suv + float2(x, y) * texel).r ? 1.0 : 0.0;
    lit /= 9;
    float ndl = saturate(dot(normalize(N), LightDir));
    return tex2D(Diffuse, uv) * (0.3 + 0.7 * ndl * lit);
}
