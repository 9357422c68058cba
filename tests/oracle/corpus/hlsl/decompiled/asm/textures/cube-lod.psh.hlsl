// ps_3_0 shader decompiled by ps30
float4 c0 : register(c0);
samplerCUBE s0 : register(s0);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = texCUBElod(s0, c0);
    return oC0;
}
