// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = 1.0 / texcoord1.x;
    r0.y = 1.0 / texcoord1.y;
    r0.z = 1.0 / texcoord1.z;
    r0.xyz = r0.xyz * texcoord0.xyz;
    r1.xyz = frac(abs(r0.xyz));
    oC0.xyz = (r0.xyz >= 0.0 ? r1.xyz : -r1.xyz) * texcoord1.xyz;
    oC0.w = 1.0;
    return oC0;
}
