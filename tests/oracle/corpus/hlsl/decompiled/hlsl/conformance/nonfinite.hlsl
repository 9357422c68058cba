// ps_3_0 shader decompiled by ps30
float4 k : register(c0);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0.x = 1.0 / (1.0 / k.x);
    oC0.y = 1.0 / (1.0 / k.y);
    oC0.w = 1.0 / k.w;
    oC0.z = (k.w * k.z);
    return oC0;
}
