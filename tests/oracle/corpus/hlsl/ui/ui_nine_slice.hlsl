// Nine-slice panel: remap UVs so borders keep their size.
sampler2D panelTex;
float4 borders;      // left, right, top, bottom in uv of the texture
float4 scaleInfo;    // xy = size ratio of the quad vs texture

float Remap(float t, float a, float b, float s)
{
    float lo = t * s;
    float hi = 1 - (1 - t) * s;
    float mid = a + (t * s - a) / (s - a - (1 - b)) * (b - a);
    return t * s < a ? lo : ((1 - t) * s < 1 - b ? hi : mid);
}

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float2 r = float2(Remap(uv.x, borders.x, borders.y, scaleInfo.x),
                      Remap(uv.y, borders.z, borders.w, scaleInfo.y));
    return tex2D(panelTex, r);
}
