// ps_3_0 shader decompiled by ps30
row_major float4x4 ViewProj : register(c4);
row_major float4x4 World : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0;
    r0 = texcoord0.x * World[0] + (World[1] * texcoord0.y);
    r0 = texcoord0.w * World[3] + (texcoord0.z * World[2] + r0);
    r1.x = dot(ViewProj[0], r0);
    r1.y = dot(ViewProj[1], r0);
    r1.z = dot(ViewProj[2], r0);
    r1.w = dot(ViewProj[3], r0);
    oC0 = r0 * 0.5 + r1;
    return oC0;
}
