// Radial (zoom) blur toward a screen-space centre, e.g. god rays or speed.
sampler2D sceneSampler;
float2 center = float2(0.5, 0.5);
float  strength;
static const int SAMPLES = 12;

float4 main(float2 texCoord : TEXCOORD0) : COLOR
{
    float2 dir = (center - texCoord) * strength / SAMPLES;
    float4 col = 0;
    float decay = 1.0, total = 0;
    for (int i = 0; i < SAMPLES; i++)
    {
        col += tex2D(sceneSampler, texCoord + dir * i) * decay;
        total += decay;
        decay *= 0.92;
    }
    return col / total;
}
