// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = 1.442695 * texcoord0;
    r1.x = exp2(r0.x);
    r1.y = exp2(r0.y);
    r1.z = exp2(r0.z);
    r1.w = exp2(r0.w);
    r2.x = exp2(-r0.x);
    r2.y = exp2(-r0.y);
    r2.z = exp2(-r0.z);
    r2.w = exp2(-r0.w);
    oC0 = (r1 - r2) * 0.5;
    return oC0;
}
