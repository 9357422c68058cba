// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0.xyz = (texcoord1.xyz - texcoord0.xyz) >= 0.0 ? 1.0 : 0.0;
    oC0.w = 1.0;
    return oC0;
}
