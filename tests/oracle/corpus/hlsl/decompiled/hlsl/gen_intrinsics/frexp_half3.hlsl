// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xyz = (-abs(texcoord0.xyz) >= 0.0 ? 1.0 : 0.0) + abs(texcoord0.xyz);
    r1.x = log2(abs(r0.x));
    r1.y = log2(abs(r0.y));
    r1.z = log2(abs(r0.z));
    r0.xyz = frac(-r1.xyz) + r1.xyz;
    r1.x = 1.0 / exp2(r0.x);
    r1.y = 1.0 / exp2(r0.y);
    r0.w = exp2(r0.z);
    r1.z = 1.0 / r0.w;
    oC0.xyz = texcoord0.xyz * r1.xyz + (r0.xyz * 0.125);
    oC0.w = 1.0;
    return oC0;
}
