// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)

void main(float4 texcoord0 : TEXCOORD0, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1, out precise float4 oC2 : COLOR2, out precise float4 oC3 : COLOR3)
{
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    oC0 = 0;
    oC1 = 0;
    oC2 = 0;
    oC3 = 0;
    r1 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    oC3 = float4(1.0, 0.5, 0.25, 2.0);
    oC0 = float4(1.0, 0.5, 0.25, 2.0);
}
