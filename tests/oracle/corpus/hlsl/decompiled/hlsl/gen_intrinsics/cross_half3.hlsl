// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xyz = texcoord0.xyz;
    oC0.xyz = r0.yzx * texcoord1.zxy - (r0.zxy * texcoord1.yzx);
    oC0.w = 1.0;
    return oC0;
}
