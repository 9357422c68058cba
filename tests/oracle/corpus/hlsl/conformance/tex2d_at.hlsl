// Conformance corpus: a 2D texture read at the interpolated t.xy and the level t.w (texldl).
sampler2D image : register(s0);

float4 main(float4 t : TEXCOORD0) : COLOR
{
    return tex2Dlod(image, t);
}
