// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)
sampler2D s0 : register(s0);

float4 main(float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r2.xy = tex2Dproj(s0, texcoord1).xy;
    r2.zw = tex2Dbias(s0, texcoord2).z;
    oC0 = r2;
    return oC0;
}
