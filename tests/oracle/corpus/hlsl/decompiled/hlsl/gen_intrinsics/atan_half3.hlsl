// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r1.xyz = max(abs(texcoord0.xyz), 1.0);
    r2.x = 1.0 / r1.x;
    r2.y = 1.0 / r1.y;
    r2.z = 1.0 / r1.z;
    r0.xyz = saturate(abs(texcoord0.xyz)) * r2.xyz;
    r1.xyz = r0.xyz * r0.xyz;
    r2.xyz = r1.xyz * (r1.xyz * 0.0208351 - 0.085133) + 0.180141;
    r1.xyz = r1.xyz * (r1.xyz * r2.xyz - 0.3302995) + 0.999866;
    r2.xyz = (r0.xyz * r1.xyz) * -2.0 + 1.5707964;
    r0.xyz = r0.xyz * r1.xyz + ((1.0 - abs(texcoord0.xyz)) >= 0.0 ? 0.0 : r2.xyz);
    oC0.xyz = r0.xyz + (min(texcoord0.xyz, 1.0) >= 0.0 ? 0.0 : -(r0.xyz + r0.xyz));
    oC0.w = 1.0;
    return oC0;
}
