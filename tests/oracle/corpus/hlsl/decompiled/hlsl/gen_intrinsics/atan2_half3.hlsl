// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0.xyz = texcoord1.xyz;
    r2.xyz = max(abs(texcoord0.xyz), abs(r0.xyz));
    r3.x = 1.0 / r2.x;
    r3.y = 1.0 / r2.y;
    r3.z = 1.0 / r2.z;
    r1.xyz = min(abs(r0.xyz), abs(texcoord0.xyz)) * r3.xyz;
    r2.xyz = r1.xyz * r1.xyz;
    r3.xyz = r2.xyz * (r2.xyz * (r2.xyz * 0.0208351 - 0.085133) + 0.180141) - 0.3302995;
    r1.xyz = r1.xyz * (r2.xyz * r3.xyz + 0.999866);
    r1.xyz = (r1.xyz * -2.0 + 1.5707964) * ((abs(r0.xyz) - abs(texcoord0.xyz)) >= 0.0 ? 0.0 : 1.0) + r1.xyz;
    r1.xyz = r1.xyz + (texcoord1.xyz >= 0.0 ? -0.0 : -3.1415927);
    r3.xyz = max(texcoord0.xyz, r0.xyz);
    r4.xyz = min(r0.xyz, texcoord0.xyz);
    oC0.xyz = (r4.xyz >= 0.0 ? 0.0 : (r3.xyz >= 0.0 ? 1.0 : 0.0)) * -(r1.xyz + r1.xyz) + r1.xyz;
    oC0.w = 1.0;
    return oC0;
}
