// ps_3_0 shader decompiled by ps30
float cutoff : register(c0);
sampler2D alphaMask : register(s0);
sampler2D col : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = (tex2D(alphaMask, texcoord0.xy).w - cutoff) >= 0.0 ? -0.0 : -1.0;
    clip(r0);
    oC0 = tex2D(col, texcoord0.xy) * saturate(texcoord1.z);
    return oC0;
}
