// Conformance corpus: a cube texture read at the direction c0.xyz and the level c0.w (texldl).
samplerCUBE faces : register(s0);
float4 at : register(c0);

float4 main() : COLOR
{
    return texCUBElod(faces, at);
}
