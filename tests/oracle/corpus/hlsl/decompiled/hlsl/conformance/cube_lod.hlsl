// ps_3_0 shader decompiled by ps30
float4 at : register(c0);
samplerCUBE faces : register(s0);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    oC0 = texCUBElod(faces, at);
    return oC0;
}
