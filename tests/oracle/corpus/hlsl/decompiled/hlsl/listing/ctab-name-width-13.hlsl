// ps_3_0 shader decompiled by ps30
float4 abcdefghijkl : register(c0);
float4 abcdefghijklm : register(c1);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = abcdefghijkl + abcdefghijklm;
    return oC0;
}
