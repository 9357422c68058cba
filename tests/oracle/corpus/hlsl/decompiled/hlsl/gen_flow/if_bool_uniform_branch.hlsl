// ps_3_0 shader decompiled by ps30
float4 x : register(c0);
bool on : register(b0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    if (on) {
        oC0 = x * texcoord0;
    } else {
        oC0 = texcoord0;
    }
    return oC0;
}
