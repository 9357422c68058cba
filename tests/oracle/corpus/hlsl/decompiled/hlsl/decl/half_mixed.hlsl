// ps_3_0 shader decompiled by ps30
float4 exactScale : register(c0);
float4 roughScale : register(c1);
sampler2D tex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 color0 : COLOR0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(tex, texcoord0.xy) * roughScale;
    r1.x = 1.0 / rsqrt(abs(dot(r0.xyz, r0.xyz)));
    oC0 = r0 * exactScale + (r1.x * color0);
    return oC0;
}
