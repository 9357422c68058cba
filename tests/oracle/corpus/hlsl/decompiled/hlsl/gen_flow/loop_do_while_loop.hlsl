// ps_3_0 shader decompiled by ps30
float4 k : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = texcoord0 * k + texcoord1;
    r1 = r0;
    r2.x = 0.0;
    for (int n0 = 0; n0 < int4(3, 0, 0, 0).x; n0++) {
        r2.y = 3.0;
        if (r2.x >= r2.y) break;
        r2.x = r2.x + 1.0;
        r1 = r1 * k + texcoord1;
    }
    oC0 = r1;
    return oC0;
}
