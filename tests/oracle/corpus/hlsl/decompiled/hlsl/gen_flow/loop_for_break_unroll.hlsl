// ps_3_0 shader decompiled by ps30
float4 w[8] : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0 = w[0] * texcoord0;
    r1 = w[1] * texcoord0 + r0;
    r2.x = (texcoord1.x - r1.x) >= 0.0 ? 0.0 : 1.0;
    r2.y = w[0].x * -texcoord0.x + texcoord1.x;
    r2.x = r2.y >= 0.0 ? r2.x : 1.0;
    r2.z = r2.y >= 0.0 ? 0.0 : 1.0;
    r2.x = -(r2.z + r2.x) >= 0.0 ? -0.0 : -1.0;
    r2.x = r2.y >= 0.0 ? r2.x : -1.0;
    r0 = r2.y >= 0.0 ? r1 : r0;
    r1 = w[2] * texcoord0 + r0;
    r0 = r2.x >= 0.0 ? r1 : r0;
    r1.x = texcoord1.x - r1.x;
    r1.x = r2.x >= 0.0 ? (r1.x >= 0.0 ? -0.0 : -1.0) : -1.0;
    r2 = w[3] * texcoord0 + r0;
    r0 = r1.x >= 0.0 ? r2 : r0;
    r1.y = (texcoord1.x - r2.x) >= 0.0 ? -0.0 : -1.0;
    r1.x = r1.x >= 0.0 ? r1.y : -1.0;
    r2 = w[4] * texcoord0 + r0;
    r0 = r1.x >= 0.0 ? r2 : r0;
    r1.y = (texcoord1.x - r2.x) >= 0.0 ? -0.0 : -1.0;
    r1.x = r1.x >= 0.0 ? r1.y : -1.0;
    r2 = w[5] * texcoord0 + r0;
    r0 = r1.x >= 0.0 ? r2 : r0;
    r1.y = (texcoord1.x - r2.x) >= 0.0 ? -0.0 : -1.0;
    r1.x = r1.x >= 0.0 ? r1.y : -1.0;
    r2 = w[6] * texcoord0 + r0;
    r0 = r1.x >= 0.0 ? r2 : r0;
    r1.y = (texcoord1.x - r2.x) >= 0.0 ? -0.0 : -1.0;
    oC0 = (r1.x >= 0.0 ? r1.y : -1.0) >= 0.0 ? (w[7] * texcoord0 + r0) : r0;
    return oC0;
}
