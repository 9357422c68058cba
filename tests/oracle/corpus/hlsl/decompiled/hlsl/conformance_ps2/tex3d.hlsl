// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
sampler3D volume : register(s2);

float4 main(float4 texcoord7 : TEXCOORD7) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = tex3D(volume, texcoord7.xyz);
    return oC0;
}
