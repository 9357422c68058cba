// oracle: target=ps_2_0
// ps_2_0 conformance: clip() on a texture coordinate, w included (texkill t0).
float4 main(float4 t : TEXCOORD0) : COLOR
{
    clip(t);
    return t;
}
