// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.x = exp2(texcoord1.x);
    r0.y = exp2(texcoord1.y);
    r0.z = exp2(texcoord1.z);
    oC0.xyz = r0.xyz * texcoord0.xyz;
    oC0.w = 1.0;
    return oC0;
}
