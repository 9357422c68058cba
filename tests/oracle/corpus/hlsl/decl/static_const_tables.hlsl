// static const arrays become def constants (or immediate values); indexed by loop and by input.
static const float3 Palette[4] = {
    float3(1, 0, 0), float3(0, 1, 0), float3(0, 0, 1), float3(1, 1, 0) };
static const float Gains[3] = { 0.5, 1.0, 2.0 };
static const float4x4 Dither = {
    0,  8,  2, 10,
   12,  4, 14,  6,
    3, 11,  1,  9,
   15,  7, 13,  5 };

float4 main(float2 uv : TEXCOORD0, float sel : TEXCOORD1) : COLOR
{
    float3 c = 0;
    [unroll] for (int i = 0; i < 3; i++) c += Palette[i] * Gains[i];
    c += Palette[(int)sel];
    return float4(c, Dither[1][2] / 16);
}
