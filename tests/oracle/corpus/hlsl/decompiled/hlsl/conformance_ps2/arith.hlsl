// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
float4 a : register(c0);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.x = rsqrt(abs(a.x));
    r0.y = 1.0 / a.y;
    r0.z = exp2(a.z);
    r0.w = log2(abs(a.w));
    oC0 = r0;
    return oC0;
}
