// Conformance corpus: a volume texture read at c0.xyz and the level c0.w (texldl).
sampler3D lut : register(s0);
float4 at : register(c0);

float4 main() : COLOR
{
    return tex3Dlod(lut, at);
}
