// ps_3_0 shader decompiled by ps30
sampler2D s0 : register(s0);
sampler2D s3 : register(s3);
sampler2D t : register(s9);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(s0, texcoord0.xy) + tex2D(s3, texcoord0.xy);
    oC0 = r0 + tex2D(t, texcoord0.xy);
    return oC0;
}
