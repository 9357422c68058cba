// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = ((abs(texcoord0.xyz) * -0.0187293 + 0.074261) * abs(texcoord0.xyz) - 0.2121144) * abs(texcoord0.xyz) + 1.5707288;
    r1.xyz = 1.0 - abs(texcoord0.xyz);
    r2.x = 1.0 / rsqrt(abs(r1.x));
    r0.w = rsqrt(abs(r1.y));
    r2.z = 1.0 / rsqrt(abs(r1.z));
    r2.y = 1.0 / r0.w;
    r0.xyz = r0.xyz * r2.xyz;
    r1.xyz = r0.xyz * -2.0 + 3.1415927;
    oC0.xyz = 1.5707964 - (r1.xyz * (texcoord0.xyz >= 0.0 ? 0.0 : 1.0) + r0.xyz);
    oC0.w = 1.0;
    return oC0;
}
