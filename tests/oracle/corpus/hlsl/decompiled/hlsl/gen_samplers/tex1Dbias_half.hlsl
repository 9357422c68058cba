// ps_3_0 shader decompiled by ps30
float4 k : register(c0);
sampler2D s : register(s5);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = tex2Dbias(s, texcoord0).zyxw * k.x;
    return oC0;
}
