// Fire billboard: two scrolling noises distort the flame shape texture.
sampler2D flameShape : register(s0);
sampler2D noiseA : register(s1);
sampler2D noiseB : register(s2);
float timeSec;
float3 scrollSpeeds = float3(1.3, 2.1, 2.3);
float2 distortion = float2(0.1, 0.2);

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float2 n1 = tex2D(noiseA, uv * float2(1, 2) - float2(0, timeSec * scrollSpeeds.x)).rg;
    float2 n2 = tex2D(noiseB, uv * float2(1, 3) - float2(0, timeSec * scrollSpeeds.y)).rg;
    float2 n = (n1 + n2 - 1) * distortion * (1 - uv.y);
    float4 f = tex2D(flameShape, saturate(uv + n));
    return f * float4(1, 0.6 + f.a * 0.4, 0.2, 1);
}
