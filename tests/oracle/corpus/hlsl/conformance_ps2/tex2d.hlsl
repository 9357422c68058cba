// oracle: target=ps_2_0
// ps_2_0 conformance: a 2D texture read at the interpolated t0.xy (texld r0, t0, s0).
sampler2D image : register(s0);

float4 main(float2 t : TEXCOORD0) : COLOR
{
    return tex2D(image, t);
}
