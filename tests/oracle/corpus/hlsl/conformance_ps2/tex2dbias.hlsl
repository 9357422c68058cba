// oracle: target=ps_2_0
// ps_2_0 conformance: a biased read, the level of detail plus the coordinate's w (texldb).
sampler2D image : register(s0);

float4 main(float4 t : TEXCOORD0) : COLOR
{
    return tex2Dbias(image, t);
}
