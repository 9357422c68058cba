// ps_3_0 shader decompiled by ps30
int4 ii : register(i3);
bool b1_ : register(b5);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0 = 0.0;
    for (int n0 = 0; n0 < ii.x; n0++) {
        r0 = r0 + texcoord0.x;
    }
    oC0 = r0;
    if (b1_) {
        oC0 = 1.0;
    }
    return oC0;
}
