// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xyz = 0.5 + texcoord0.xyz;
    oC0.xyz = r0.xyz - frac(r0.xyz);
    oC0.w = 1.0;
    return oC0;
}
