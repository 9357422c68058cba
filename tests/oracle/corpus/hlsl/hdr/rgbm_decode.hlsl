// HDR stored as RGBM in an 8-bit target: decode, expose, re-encode as RGBM.
sampler2D rgbmTex;
float rgbmRange = 6.0;
float exposureScale;

float3 DecodeRGBM(float4 r) { return r.rgb * r.a * rgbmRange; }

float4 EncodeRGBM(float3 c)
{
    c /= rgbmRange;
    float m = saturate(max(max(c.r, c.g), max(c.b, 1e-6)));
    m = ceil(m * 255) / 255;
    return float4(c / m, m);
}

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    return EncodeRGBM(DecodeRGBM(tex2D(rgbmTex, uv)) * exposureScale);
}
