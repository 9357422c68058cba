// ps_3_0 shader decompiled by ps30
sampler2D s0 : register(s0);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = tex2D(s0, float2(0.625, 0.125));
    return oC0;
}
