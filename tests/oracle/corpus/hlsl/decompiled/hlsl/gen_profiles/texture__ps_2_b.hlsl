// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)
sampler2D s : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = tex2D(s, texcoord0.xy);
    return oC0;
}
