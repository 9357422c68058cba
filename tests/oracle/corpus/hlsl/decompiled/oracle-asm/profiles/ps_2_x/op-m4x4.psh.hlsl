// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)
float4 c1 : register(c1);
float4 c2 : register(c2);
float4 c3 : register(c3);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = float4(1.0, 0.5, 0.25, 2.0);
    r1 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    oC0 = float4(dot(r1, float4(1.0, 0.5, 0.25, 2.0)), dot(r1, c1), dot(r1, c2), dot(r1, c3));
    return oC0;
}
