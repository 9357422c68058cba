// oracle: target=ps_2_0
// ps_2_0 conformance: a projective read, the coordinate divided by its w (texldp).
sampler2D image : register(s0);

float4 main(float4 t : TEXCOORD1) : COLOR
{
    return tex2Dproj(image, t);
}
