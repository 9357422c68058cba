// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)
float threshold : register(c0);
sampler2D a : register(s0);
sampler2D b : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 color0 : COLOR0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xy = ddx(texcoord0.xy);
    r0.xy = r0.xy + r0.xy;
    r0.zw = ddy(texcoord0.xy);
    r0 = tex2Dgrad(a, texcoord0.xy, r0.xy, (r0.zw + r0.zw));
    r1 = tex2D(b, r0.xy);
    r2.xy = r1.zw;
    r1 = tex2D(b, (r1.xy + tex2D(a, r2.xy).xy));
    r1 = (threshold - r0.x) >= 0.0 ? r1 : (r1 * color0);
    r0.x = r0.y - threshold;
    r1.w = r0.x >= 0.0 ? r1.w : r0.w;
    oC0 = r1;
    return oC0;
}
