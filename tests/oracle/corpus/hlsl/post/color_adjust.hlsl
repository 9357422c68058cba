// Brightness, contrast, saturation, tint and lift/gamma/gain.
sampler2D Screen;
float Brightness, Contrast = 1, Saturation = 1;
float3 Tint = 1;
float3 Lift, Gamma = 1, Gain = 1;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float3 c = tex2D(Screen, uv).rgb;
    c = (c - 0.5) * Contrast + 0.5 + Brightness;
    float grey = dot(c, float3(0.299, 0.587, 0.114));
    c = lerp(grey.xxx, c, Saturation) * Tint;
    c = Gain * (c + Lift * (1 - c));
    c = pow(max(c, 0), 1 / Gamma);
    return float4(c, 1);
}
