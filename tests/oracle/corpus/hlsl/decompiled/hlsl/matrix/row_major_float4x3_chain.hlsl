// ps_3_0 shader decompiled by ps30
row_major float4x3 Bone : register(c0);
row_major float3x3 Rotation : register(c4);
float4 tint : register(c7);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xyz = mul(texcoord0, Bone);
    r0.xyw = r0.x * Rotation[0] + (r0.y * Rotation[1]);
    r0.xyz = r0.z * Rotation[2] + r0.xyw;
    r0.w = 1.0;
    oC0 = r0 * tint;
    return oC0;
}
