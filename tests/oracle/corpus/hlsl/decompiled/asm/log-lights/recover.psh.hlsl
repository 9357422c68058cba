// ps_3_0 shader decompiled by ps30
sampler2D s0 : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(s0, texcoord0.xy);
    r1.x = log2(abs(r0.x));
    r1.y = log2(abs(r0.y));
    r1.z = log2(abs(r0.z));
    r1.w = log2(abs(r0.w));
    oC0 = -r1;
    return oC0;
}
