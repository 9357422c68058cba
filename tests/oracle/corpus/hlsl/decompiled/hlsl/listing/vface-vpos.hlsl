// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float vface : VFACE, float2 vpos : VPOS) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    oC0 = -(vface >= 0.0 ? 1.0 : -1.0) >= 0.0 ? vpos.xyxy : texcoord0.xyxy;
    return oC0;
}
