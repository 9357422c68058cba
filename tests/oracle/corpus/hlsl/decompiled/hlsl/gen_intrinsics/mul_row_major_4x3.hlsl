// ps_3_0 shader decompiled by ps30
row_major float4x3 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0;
    r0.xyz = texcoord0.x * M[0] + (M[1] * texcoord0.y);
    oC0.xyz = texcoord0.w * M[3] + (texcoord0.z * M[2] + r0.xyz);
    oC0.w = 0.0;
    return oC0;
}
