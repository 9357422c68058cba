// ps_3_0 shader decompiled by ps30
float4x4 matCM : register(c4);
row_major float4x4 matRM : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = mul(texcoord0, matRM) + mul(texcoord0, matCM);
    r0 = r0 + mul(matRM, texcoord0);
    oC0 = r0 + mul(matCM, texcoord0);
    return oC0;
}
