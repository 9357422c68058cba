// oracle: target=ps_2_0
// ps_2_0 conformance: a cube-map read along the interpolated direction t2.xyz.
samplerCUBE sky : register(s1);

float4 main(float3 d : TEXCOORD2) : COLOR
{
    return texCUBE(sky, d);
}
