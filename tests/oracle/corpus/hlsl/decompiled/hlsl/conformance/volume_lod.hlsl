// ps_3_0 shader decompiled by ps30
float4 at : register(c0);
sampler3D lut : register(s0);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    oC0 = tex3Dlod(lut, at);
    return oC0;
}
