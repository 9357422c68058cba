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
    r0 = r1 - r2;
    r1 = r1 + r2;
    r2.x = 1.0 / r1.x;
    r2.y = 1.0 / r1.y;
    r2.z = 1.0 / r1.z;
    r2.w = 1.0 / r1.w;
    oC0 = r0 * r2;
    return oC0;
}
