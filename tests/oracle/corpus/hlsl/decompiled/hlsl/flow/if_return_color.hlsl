// ps_3_0 shader decompiled by ps30
float4 colorA : register(c1);
float4 colorB : register(c2);
float threshold : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = texcoord0.x - threshold;
    if (texcoord0.x < threshold) {
        r1 = colorA;
    } else {
        r1 = 0.0;
    }
    oC0 = r0.x >= 0.0 ? colorB : r1;
    return oC0;
}
