// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)
sampler2D s0 : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r2 = tex2Dgrad(s0, texcoord0.xy, float2(0.5, 0.0), float4(0.0, 0.5, 0.0, 0.0).xy);
    r3.x = ddx(texcoord0).x;
    r3.y = ddy(texcoord0).y;
    r3.z = r2.y;
    r3.w = r2.x;
    oC0 = r3;
    return oC0;
}
