// ps_3_0 shader decompiled by ps30
sampler2D glyphs : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 color0 : COLOR0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(glyphs, texcoord0.xy);
    r1 = r0.w - 0.0019607844;
    oC0.w = r0.w * color0.w;
    clip(r1);
    oC0.xyz = color0.xyz;
    return oC0;
}
