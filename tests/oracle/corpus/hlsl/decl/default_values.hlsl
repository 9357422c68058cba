// Uniforms with default values of many shapes; the constant table carries them.
float  Scalar = 0.5;
float2 Pair = { 1.0, 2.0 };
float3 Colour = float3(0.25, 0.5, 0.75);
float4 Vec = float4(1, 0, 0, 1);
float4x4 Ident = { 1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1 };
float  Table[4] = { 0.1, 0.2, 0.3, 0.4 };
int    Count = 3;
bool   Enabled = true;
float  Soft = 0.75;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 r = mul(v, Ident) * Vec * Scalar + float4(Colour, Pair.x) * Pair.y;
    for (int i = 0; i < Count; i++)
        r += Table[i];
    if (Enabled) r *= Soft;
    return r;
}
