// ps_3_0 shader decompiled by ps30
float _bias : register(c1);
float4 _scale : register(c0);
sampler2D _img : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    oC0 = tex2D(_img, texcoord0.xy) * _scale + _bias;
    return oC0;
}
