// ps_3_0 shader decompiled by ps30
float4 weights[4] : register(c0);
sampler2D tex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(tex, (weights[1].xy + texcoord0.xy));
    r0 = tex2D(tex, (weights[0].xy + texcoord0.xy)) * weights[0].w + (r0 * weights[1].w);
    r0 = tex2D(tex, (weights[2].xy + texcoord0.xy)) * weights[2].w + r0;
    oC0 = tex2D(tex, (weights[3].xy + texcoord0.xy)) * weights[3].w + r0;
    return oC0;
}
