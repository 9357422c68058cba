// Reinhard operator on luminance with an exposure scale and white point.
sampler2D hdrScene : register(s0);
sampler2D avgLum   : register(s1);   // 1x1 adapted luminance
float middleGrey = 0.18;
float whitePoint = 4.0;

static const float3 LUM = float3(0.2126, 0.7152, 0.0722);

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float3 c = tex2D(hdrScene, uv).rgb;
    float La = tex2D(avgLum, float2(0.5, 0.5)).r;
    float L = dot(c, LUM) * middleGrey / (La + 0.001);
    float Ld = L * (1 + L / (whitePoint * whitePoint)) / (1 + L);
    return float4(c * (Ld / max(dot(c, LUM), 1e-5)), 1);
}
