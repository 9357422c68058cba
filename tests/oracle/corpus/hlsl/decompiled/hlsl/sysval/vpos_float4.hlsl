// ps_3_0 shader decompiled by ps30

float4 main(float2 vpos : VPOS) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.x = frac((dot(vpos, float2(0.06711056, 0.00583715)) + 0.0));
    oC0.xyz = frac((r0.x * 52.982918));
    oC0.w = 1.0;
    return oC0;
}
