// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    oC0.x = 1.0 / texcoord0.x;
    oC0.y = 1.0 / texcoord0.y;
    oC0.z = 1.0 / texcoord0.z;
    oC0.w = 1.0 / texcoord0.w;
    return oC0;
}
