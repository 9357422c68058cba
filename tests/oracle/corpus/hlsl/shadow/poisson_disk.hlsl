// 16-tap Poisson disk PCF, radius scaled by receiver depth.
sampler2D g_ShadowMap : register(s3);
float g_FilterRadius;
float g_Bias;

static const float2 Poisson[16] =
{
    float2(-0.94201624, -0.39906216), float2( 0.94558609, -0.76890725),
    float2(-0.09418410, -0.92938870), float2( 0.34495938,  0.29387760),
    float2(-0.91588581,  0.45771432), float2(-0.81544232, -0.87912464),
    float2(-0.38277543,  0.27676845), float2( 0.97484398,  0.75648379),
    float2( 0.44323325, -0.97511554), float2( 0.53742981, -0.47373420),
    float2(-0.26496911, -0.41893023), float2( 0.79197514,  0.19090188),
    float2(-0.24188840,  0.99706507), float2(-0.81409955,  0.91437590),
    float2( 0.19984126,  0.78641367), float2( 0.14383161, -0.14100790)
};

float4 main(float4 lp : TEXCOORD0) : COLOR
{
    float3 s = lp.xyz / lp.w;
    float2 uv = s.xy * float2(0.5, -0.5) + 0.5;
    float vis = 0;
    for (int i = 0; i < 16; i++)
    {
        float d = tex2D(g_ShadowMap, uv + Poisson[i] * g_FilterRadius).r;
        vis += (s.z - g_Bias > d) ? 0.0 : 1.0 / 16;
    }
    return float4(vis.xxx, 1);
}
