// ps_3_0 shader decompiled by ps30
float2 d : register(c0);
sampler2D s : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(s, (d + texcoord0.xy)) + tex2D(s, texcoord0.xy);
    r1.xy = d * 2.0 + texcoord0.xy;
    oC0 = r0 + tex2D(s, r1.xy);
    return oC0;
}
