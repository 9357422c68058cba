// Refused by D3DCompile (X4532, E_NOTIMPL): noise() only exists for texture shaders (tx_1_0,
// used to fill procedural textures); a pixel shader cannot map it to an instruction.
sampler2D baseTex;
float noiseScale;

float4 main(float2 uv : TEXCOORD0, float3 wpos : TEXCOORD1) : COLOR
{
    float n = noise(wpos * noiseScale);
    return tex2D(baseTex, uv) * (0.8 + 0.2 * n);
}
