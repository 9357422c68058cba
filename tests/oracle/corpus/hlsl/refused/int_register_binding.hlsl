// Refused by D3DCompile (X4509): an int uniform bound with register(i#) alone; Microsoft wants a
// c register binding as well. decl/register_bindings.hlsl drops the i binding.
// Explicit register(c#)/register(s#)/register(b#)/register(i#) bindings, with gaps.
sampler2D Albedo     : register(s3);
samplerCUBE Reflect  : register(s7);
float4   Tint        : register(c10);
float4x4 ReflMatrix  : register(c20);
float4   Offsets[3]  : register(c40);
bool     UseReflect  : register(b3);
int      Taps        : register(i2);

float4 main(float2 uv : TEXCOORD0, float3 r : TEXCOORD1) : COLOR
{
    float4 c = 0;
    for (int i = 0; i < Taps; i++)
        c += tex2D(Albedo, uv + Offsets[i].xy);
    c *= Tint;
    if (UseReflect)
        c += texCUBE(Reflect, mul(float4(r, 0), ReflMatrix).xyz);
    return c;
}
