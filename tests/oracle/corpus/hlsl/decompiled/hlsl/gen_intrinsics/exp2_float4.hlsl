// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    oC0.x = exp2(texcoord0.x);
    oC0.y = exp2(texcoord0.y);
    oC0.z = exp2(texcoord0.z);
    oC0.w = exp2(texcoord0.w);
    return oC0;
}
