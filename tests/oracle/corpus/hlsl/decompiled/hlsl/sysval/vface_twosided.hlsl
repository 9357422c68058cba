// ps_3_0 shader decompiled by ps30
sampler2D frontTex : register(s0);
sampler2D backTex : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float vface : VFACE) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    oC0 = vface.xxxx >= 0.0 ? tex2D(frontTex, texcoord0.xy) : tex2D(backTex, texcoord0.xy);
    return oC0;
}
