// Conformance corpus: clip() on a four-component value: the pixel is discarded when any
// component, w included, is negative (texkill).
float4 main(float4 t : TEXCOORD0) : COLOR
{
    clip(t);
    return t;
}
