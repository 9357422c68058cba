// ps_3_0 shader decompiled by ps30
float4x4 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = mul(M, texcoord0);
    return oC0;
}
