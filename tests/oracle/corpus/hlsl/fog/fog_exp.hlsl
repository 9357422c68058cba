// Exponential fog in both forms, chosen by a bool uniform.
sampler2D tex;
float3 FogColour;
float  FogDensity;
bool   UseExp2;

float4 main(float2 uv : TEXCOORD0, float3 viewPos : TEXCOORD1) : COLOR
{
    float d = length(viewPos);
    float f;
    if (UseExp2)
    {
        float dd = d * FogDensity;
        f = exp2(-dd * dd * 1.442695);
    }
    else
        f = exp(-d * FogDensity);
    float4 c = tex2D(tex, uv);
    c.rgb = lerp(FogColour, c.rgb, saturate(f));
    return c;
}
