// ps_3_0 shader decompiled by ps30
float4 b : register(c0); // the table's type: bool
float4 k : register(c1);
bool b_ : register(b0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    if (b_) {
        r0 = k * texcoord0;
    } else {
        r0 = 0.0;
    }
    oC0 = -b.x >= 0.0 ? texcoord0 : r0;
    return oC0;
}
