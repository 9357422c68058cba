// ps_3_0 shader decompiled by ps30
float4x4 proj : register(c0);
row_major float3x4 rm3x4 : register(c4);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = proj._m20;
    r0.y = proj._m21;
    r0.z = proj._m22;
    r0.w = proj._m23;
    r0.z = dot(r0, texcoord0) + proj._m22;
    r0.x = dot(proj._m00_m00, texcoord0.xy) + proj._m00;
    r0.y = proj._m11 + rm3x4[1].w;
    r0.w = proj._m22;
    oC0 = r0 + rm3x4[0];
    return oC0;
}
