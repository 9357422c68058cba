// oracle: target=ps_2_0
// ps_2_0 conformance: the interpolated texture coordinate as the colour (dcl t0).
float4 main(float4 t : TEXCOORD0) : COLOR
{
    return t;
}
