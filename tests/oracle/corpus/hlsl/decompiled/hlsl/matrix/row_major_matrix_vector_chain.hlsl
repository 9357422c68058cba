// ps_3_0 shader decompiled by ps30
row_major float4x4 A : register(c0);
row_major float4x4 B : register(c4);
float4x4 C : register(c8);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = mul(C, texcoord0);
    r1 = mul(A, texcoord0);
    oC0 = mul(C, r0) + mul(B, r1);
    return oC0;
}
