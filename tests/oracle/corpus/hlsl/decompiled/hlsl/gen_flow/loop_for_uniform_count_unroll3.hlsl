// ps_3_0 shader decompiled by ps30
float4 n : register(c3); // the table's type: int
float4 w[3] : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xy = float2(0.0, 1.0);
    r0.y = -n.x >= 0.0 ? r0.x : r0.y;
    r0.z = r0.y - n.x;
    r0.y = r0.z >= 0.0 ? r0.y : 2.0;
    r0.y = (r0.y - n.x) >= 0.0 ? -0.0 : -1.0;
    r1 = -n.x >= 0.0 ? r0.x : (w[0] * texcoord0);
    r1 = r0.z >= 0.0 ? r1 : (w[1] * texcoord0 + r1);
    oC0 = (r0.z >= 0.0 ? 0.0 : r0.y) >= 0.0 ? r1 : (w[2] * texcoord0 + r1);
    return oC0;
}
