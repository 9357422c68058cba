// ps_3_0 shader decompiled by ps30
float4 bv : register(c2);
float4 bv2 : register(c3); // the table's type: bool2
float4 iv : register(c0);
float4 iv2 : register(c1); // the table's type: int2

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = texcoord0 * iv + iv2.xyxy;
    r0 = -bv.x >= 0.0 ? -r0 : r0;
    r0.xy = r0.xy + bv2.y;
    oC0 = r0 * (-bv.w >= 0.0 ? 1.0 : 2.0);
    return oC0;
}
