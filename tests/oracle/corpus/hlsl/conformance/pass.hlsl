// Conformance corpus: the interpolated texture coordinate as the colour, for the per-pixel
// state around the shader (alpha test, clip planes).
float4 main(float4 t : TEXCOORD0) : COLOR
{
    return t;
}
