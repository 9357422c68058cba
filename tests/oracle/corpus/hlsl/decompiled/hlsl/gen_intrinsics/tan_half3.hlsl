// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = frac((texcoord0.xyz * 0.15915494 + 0.25)) * 6.2831855 - 3.1415927;
    r0.xyz = r0.xyz * r0.xyz;
    r1.xyz = r0.xyz * (r0.xyz * (r0.xyz * -2.523985e-7 + 2.47609e-5) - 0.0013888397) + 0.04166664;
    r0.xyz = r0.xyz * (r0.xyz * r1.xyz - 0.5) + 1.0;
    r1.xyz = frac((texcoord0.xyz * 0.15915494 + 0.5)) * 6.2831855 - 3.1415927;
    r1.xyz = r1.xyz * r1.xyz;
    r2.xyz = r1.xyz * (r1.xyz * (r1.xyz * -2.523985e-7 + 2.47609e-5) - 0.0013888397) + 0.04166664;
    r1.xyz = r1.xyz * (r1.xyz * r2.xyz - 0.5) + 1.0;
    r2.x = 1.0 / r1.x;
    r2.y = 1.0 / r1.y;
    r2.z = 1.0 / r1.z;
    oC0.xyz = r0.xyz * r2.xyz;
    oC0.w = 1.0;
    return oC0;
}
