// ps_3_0 shader decompiled by ps30
float4 splitsAndBias : register(c0);
sampler2D s4 : register(s4);
sampler2D s6 : register(s6);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xzw = tex2D(s4, texcoord0.xy).x * float3(1.0, 0.0, 0.0) + float3(0.0, 0.0, 1.0);
    r0.y = tex2D(s6, texcoord0.zw).x;
    oC0 = r0 * splitsAndBias;
    return oC0;
}
