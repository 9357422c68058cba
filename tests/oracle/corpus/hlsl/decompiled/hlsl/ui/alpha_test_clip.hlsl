// ps_3_0 shader decompiled by ps30
float alphaCutoff : register(c1);
float4 tint : register(c0);
sampler2D spriteTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 color0 : COLOR0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(spriteTex, texcoord0.xy) * color0;
    r1 = r0.w * tint.w - alphaCutoff;
    oC0 = (r0 * tint);
    clip(r1);
    return oC0;
}
