// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
sampler2D image : register(s0);

float4 main(float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = tex2Dproj(image, texcoord1);
    return oC0;
}
