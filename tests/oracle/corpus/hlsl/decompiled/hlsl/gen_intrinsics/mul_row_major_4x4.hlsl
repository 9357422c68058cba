// ps_3_0 shader decompiled by ps30
row_major float4x4 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0;
    r0 = texcoord0.z * M[2] + (texcoord0.x * M[0] + (M[1] * texcoord0.y));
    r1.x = dot(M[0], texcoord0);
    r1.y = dot(M[1], texcoord0);
    r1.z = dot(M[2], texcoord0);
    r1.w = dot(M[3], texcoord0);
    oC0 = (texcoord0.w * M[3] + r0) + r1;
    return oC0;
}
