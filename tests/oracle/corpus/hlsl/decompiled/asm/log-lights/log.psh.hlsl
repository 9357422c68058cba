// ps_3_0 shader decompiled by ps30
float4 c0 : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    oC0 = exp2(-(texcoord0.x * c0.x)).xxxx;
    return oC0;
}
