// oracle: target=ps_2_0
// ps_2_0 conformance: the two colour inputs (dcl v0, dcl v1), which Direct3D 9 gives the
// shader in [0, 1]: their difference shows each one's clamp.
float4 main(float4 diffuse : COLOR0, float4 specular : COLOR1) : COLOR
{
    return diffuse - specular;
}
