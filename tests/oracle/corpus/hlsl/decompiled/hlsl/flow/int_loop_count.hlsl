// ps_3_0 shader decompiled by ps30
float4 step4 : register(c0);
int4 iterations : register(i0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = texcoord0;
    for (int n0 = 0; n0 < iterations.x; n0++) {
        r1.x = 0.5;
        r0 = r0 * r1.x + step4;
    }
    oC0 = r0;
    return oC0;
}
