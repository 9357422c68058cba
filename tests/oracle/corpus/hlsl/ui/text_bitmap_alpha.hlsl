// Bitmap font from an A8 atlas; the glyph's alpha is the coverage.
sampler2D glyphs;

float4 main(float2 uv : TEXCOORD0, float4 color : COLOR0) : COLOR
{
    float a = tex2D(glyphs, uv).a;
    clip(a - 0.5 / 255);
    return float4(color.rgb, color.a * a);
}
