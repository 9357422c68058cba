// Uniforms declared but unused: they vanish from the constant table.
float4 used;
float4 unusedVector;
float4x4 unusedMatrix;
sampler2D unusedSampler;
sampler2D usedSampler;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    return tex2D(usedSampler, uv) * used;
}
