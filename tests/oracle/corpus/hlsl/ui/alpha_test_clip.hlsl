// UI sprite with alpha test through clip() and a tint.
sampler2D spriteTex;
float4 tint = float4(1, 1, 1, 1);
float alphaCutoff = 0.01;

float4 main(float2 uv : TEXCOORD0, float4 vc : COLOR0) : COLOR
{
    float4 c = tex2D(spriteTex, uv) * vc * tint;
    clip(c.a - alphaCutoff);
    return c;
}
