// Last pass: exp of the average log luminance, adapted over time toward the target.
sampler2D curLum  : register(s0);
sampler2D prevLum : register(s1);
float4 sampleOffsets[4];
float elapsedTime;
float adaptRate = 1.5;

float4 main(float2 t : TEXCOORD0) : COLOR0
{
    float acc = 0;
    for (int i = 0; i < 4; i++)
        acc += tex2D(curLum, t + sampleOffsets[i].xy).r;
    float target = exp(acc * 0.25);
    float prev = tex2D(prevLum, float2(0.5, 0.5)).r;
    float adapted = prev + (target - prev) * (1 - exp(-elapsedTime * adaptRate));
    return float4(adapted.xxx, 1);
}
