// Sampler array used with constant indices, some skipped.
sampler2D shadowCascades[4] : register(s4);
float4 splitsAndBias;

float4 main(float4 p : TEXCOORD0) : COLOR
{
    float a = tex2D(shadowCascades[0], p.xy).r;
    float c = tex2D(shadowCascades[2], p.zw).r;
    return float4(a, c, 0, 1) * splitsAndBias;
}
