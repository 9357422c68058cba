// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
float4 k : register(c0);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = 1.0 / (1.0 / k.x);
    r0.y = 1.0 / (1.0 / k.y);
    r0.z = k.w * k.z;
    r0.w = 1.0 / k.w;
    r0.x = r0.x;
    r0.y = r0.y;
    r0.z = r0.z;
    r0.w = r0.w;
    oC0 = r0;
    return oC0;
}
