// Matrices built in the shader from interpolants, float2x2 rotation of UVs.
sampler2D decal;
float angle;

float4 main(float2 uv : TEXCOORD0, float3 T : TEXCOORD1, float3 B : TEXCOORD2, float3 N : TEXCOORD3) : COLOR
{
    float s, c;
    sincos(angle, s, c);
    float2x2 rot = float2x2(c, -s, s, c);
    float2 ruv = mul(rot, uv - 0.5) + 0.5;
    float3x3 frame = float3x3(T, B, N);
    float3 n = mul(frame, float3(0, 0, 1));
    return tex2D(decal, ruv) * float4(n * 0.5 + 0.5, 1);
}
