// ps_3_0 shader decompiled by ps30
float4 n : register(c8); // the table's type: int
float4 w[8] : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r1.xy = float2(0.0, 1.0);
    r0 = -n.x >= 0.0 ? r1.x : (w[0] * texcoord0);
    r1.x = -n.x >= 0.0 ? r1.x : r1.y;
    r1.y = r1.x - n.x;
    r1.x = r1.y >= 0.0 ? r1.x : 2.0;
    r0 = r1.y >= 0.0 ? r0 : (w[1] * texcoord0 + r0);
    r1.z = (r1.x - n.x) >= 0.0 ? -0.0 : -1.0;
    r1.y = r1.y >= 0.0 ? -0.0 : r1.z;
    r0 = r1.y >= 0.0 ? r0 : (w[2] * texcoord0 + r0);
    r1.x = r1.y >= 0.0 ? r1.x : 3.0;
    r1.z = r1.x - n.x;
    r1.y = r1.z >= 0.0 ? -0.0 : r1.y;
    r0 = r1.y >= 0.0 ? r0 : (w[3] * texcoord0 + r0);
    r1.x = r1.y >= 0.0 ? r1.x : 4.0;
    r1.z = r1.x - n.x;
    r1.y = r1.z >= 0.0 ? -0.0 : r1.y;
    r0 = r1.y >= 0.0 ? r0 : (w[4] * texcoord0 + r0);
    r1.x = r1.y >= 0.0 ? r1.x : 5.0;
    r1.z = r1.x - n.x;
    r1.y = r1.z >= 0.0 ? -0.0 : r1.y;
    r0 = r1.y >= 0.0 ? r0 : (w[5] * texcoord0 + r0);
    r1.x = r1.y >= 0.0 ? r1.x : 6.0;
    r1.z = r1.x - n.x;
    r1.y = r1.z >= 0.0 ? -0.0 : r1.y;
    r0 = r1.y >= 0.0 ? r0 : (w[6] * texcoord0 + r0);
    r1.x = (r1.y >= 0.0 ? r1.x : 7.0) - n.x;
    oC0 = (r1.x >= 0.0 ? -0.0 : r1.y) >= 0.0 ? r0 : (w[7] * texcoord0 + r0);
    return oC0;
}
