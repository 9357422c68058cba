// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = 1.442695 * texcoord0.xyz;
    r1.x = exp2(r0.x);
    r1.y = exp2(r0.y);
    r1.z = exp2(r0.z);
    r2.x = exp2(-r0.x);
    r2.y = exp2(-r0.y);
    r2.z = exp2(-r0.z);
    oC0.xyz = (r1.xyz - r2.xyz) * 0.5;
    oC0.w = 1.0;
    return oC0;
}
