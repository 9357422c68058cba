// ps_3_0 shader decompiled by ps30
float4 k : register(c0);
sampler2D s : register(s5);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    oC0 = tex2Dgrad(s, texcoord0.x.xx, texcoord1.x.xx, texcoord2.xx).zyxw * k.x;
    return oC0;
}
