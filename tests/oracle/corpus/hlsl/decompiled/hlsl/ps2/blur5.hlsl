// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
float2 texel : register(c5);
float4 weights[5] : register(c0);
sampler2D src : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r1.xy = texel;
    r2.xy = r1.xy * -2.0 + texcoord0.xy;
    r1.xy = r1.xy * 2.0 + texcoord0.xy;
    r0 = tex2D(src, (texcoord0.xy - texel));
    r0 = tex2D(src, r2.xy) * weights[0].x + (r0 * weights[1].x);
    r0 = tex2D(src, (texcoord0.xy + texel)) * weights[3].x + (tex2D(src, texcoord0.xy) * weights[2].x + r0);
    oC0 = (tex2D(src, r1.xy) * weights[4].x + r0);
    return oC0;
}
