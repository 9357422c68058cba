// ps_3_0 shader decompiled by ps30
float3x3 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0.xyz = mul(M, texcoord0.xyz);
    oC0.w = 1.0;
    return oC0;
}
