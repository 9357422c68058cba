// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.xy = ddx(texcoord0.xy);
    r0.zw = ddy(texcoord0.xy);
    oC0 = r0;
    return oC0;
}
