// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    oC0.yzw = (texcoord0.yzy * float3(1.0, 1.0, 0.0) + float3(0.0, 0.0, 1.0)) * (texcoord1.yyw * float3(1.0, 0.0, 1.0) + float3(0.0, 1.0, 0.0));
    oC0.x = 1.0;
    return oC0;
}
