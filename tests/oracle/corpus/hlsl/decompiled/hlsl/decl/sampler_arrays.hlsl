// ps_3_0 shader decompiled by ps30
float4 weights : register(c0);
sampler2D s0 : register(s0);
sampler2D s1 : register(s1);
sampler2D s2 : register(s2);
sampler2D s3 : register(s3);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(s0, texcoord0.xy) * weights.x + (tex2D(s1, texcoord0.xy) * weights.y);
    r0 = tex2D(s2, texcoord0.xy) * weights.z + r0;
    oC0 = tex2D(s3, texcoord0.xy) * weights.w + r0;
    return oC0;
}
