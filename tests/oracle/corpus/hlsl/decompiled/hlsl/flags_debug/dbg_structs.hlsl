// ps_3_0 shader decompiled by ps30
sampler2D tex : register(s0);

void main(float4 texcoord0 : TEXCOORD0, float4 color0 : COLOR0, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1)
{
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    oC0 = 0;
    oC1 = 0;
    r0.xyz = 2.0 * color0.xyz;
    r0.w = 1.0;
    r0 = r0 * tex2D(tex, texcoord0.xy);
    oC0 = r0;
    oC1 = (color0.w * r0);
}
