// Bloom bright pass: threshold with a soft knee, outputs pre-multiplied colour.
sampler2D SceneSampler;
sampler2D LumSampler;
float Threshold = 1.0;
float Knee = 0.5;
float MiddleGray;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float3 c = tex2D(SceneSampler, uv).rgb;
    float lum = tex2D(LumSampler, float2(0.5, 0.5)).r;
    c *= MiddleGray / (lum + 0.001);
    float br = max(c.r, max(c.g, c.b));
    float soft = clamp(br - Threshold + Knee, 0, 2 * Knee);
    soft = soft * soft / (4 * Knee + 0.00001);
    float contrib = max(soft, br - Threshold) / max(br, 0.00001);
    return float4(c * contrib, 1);
}
