// ps_3_0 shader decompiled by ps30
float4 k : register(c0);
int4 n : register(i0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0 = texcoord0;
    for (int n0 = 0; n0 < n.x; n0++) {
        r0 = r0 * k + texcoord0;
    }
    oC0 = r0;
    return oC0;
}
