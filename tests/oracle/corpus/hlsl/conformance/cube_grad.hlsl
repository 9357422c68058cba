// Conformance corpus: a cube texture read at an interpolated direction, its level of detail
// from the quad's derivatives (texld).
samplerCUBE faces : register(s0);

float4 main(float3 dir : TEXCOORD0) : COLOR
{
    return texCUBE(faces, dir);
}
