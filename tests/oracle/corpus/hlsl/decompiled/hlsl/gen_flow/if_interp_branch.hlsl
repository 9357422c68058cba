// ps_3_0 shader decompiled by ps30
float4 x : register(c0);
float4 y : register(c1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.x = texcoord1.x;
    if (r0.x < texcoord0.x) {
        oC0 = x * texcoord0;
    } else {
        oC0 = y * texcoord1;
    }
    return oC0;
}
