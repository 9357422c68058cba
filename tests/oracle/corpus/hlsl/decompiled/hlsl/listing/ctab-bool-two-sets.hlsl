// ps_3_0 shader decompiled by ps30
float4 bb : register(c0); // the table's type: bool
bool bb_ : register(b0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = bb.x * texcoord0.xyxy;
    if (bb_) {
        r1.x = bb.x;
        oC0 = texcoord0.xyxy * r1.x + 1.0;
    } else {
        oC0 = r0;
    }
    return oC0;
}
