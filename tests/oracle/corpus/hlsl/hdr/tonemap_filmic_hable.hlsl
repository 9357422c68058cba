// Hable's filmic curve (Uncharted 2 constants) with gamma out.
sampler2D sceneTex;
float exposure = 2.0;

static const float A = 0.15, B = 0.50, C = 0.10, D = 0.20, E = 0.02, F = 0.30, W = 11.2;

float3 Curve(float3 x)
{
    return ((x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F)) - E / F;
}

float4 main(float2 texCoord : TEXCOORD0) : COLOR
{
    float3 hdr = tex2D(sceneTex, texCoord).rgb * exposure;
    float3 mapped = Curve(hdr) / Curve(W);
    return float4(pow(mapped, 1 / 2.2), 1);
}
