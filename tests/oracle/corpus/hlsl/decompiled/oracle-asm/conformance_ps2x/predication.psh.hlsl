// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    bool4 p0 = false;
    r0 = float4(0.25, 0.25, 0.25, 0.25);
    p0 = texcoord0 > float4(0.5, 0.5, 0.5, 0.5);
    r0 = p0 ? (float4(1.0, 1.0, 1.0, 1.0)) : r0;
    oC0 = r0;
    return oC0;
}
