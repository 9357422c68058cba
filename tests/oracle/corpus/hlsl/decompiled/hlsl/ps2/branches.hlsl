// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)
float2 step : register(c2);
float4 tint : register(c1);
float4 useTint : register(c0); // the table's type: bool
sampler2D tex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = tex2D(tex, texcoord0.xy);
    r0 = r0 * step.x + (r0.wzyx * step.y);
    r0 = (1.0 - r0.w) >= 0.0 ? r0 : (r0 * (1.0 / r0.w));
    r1 = r0 * tint;
    oC0 = (-useTint.x >= 0.0 ? r0 : r1);
    return oC0;
}
