// ps_3_0 shader decompiled by ps30
float t : register(c2);
float4 x : register(c0);
float4 y : register(c1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.x = 0.5;
    if (r0.x < t) {
        r0 = x;
        oC0 = r0 * texcoord0 + y;
    } else {
        oC0 = texcoord0;
    }
    return oC0;
}
