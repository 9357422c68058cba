// ps_3_0 shader decompiled by ps30
float4 abcdefghijkl : register(c1);
float4 g_vMaterialDiffuseColorAndOpacity : register(c0);
float4 x : register(c2);
sampler2D g_samplerDiffuseAlbedoWithAlpha : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    oC0 = tex2D(g_samplerDiffuseAlbedoWithAlpha, texcoord0.xy) * g_vMaterialDiffuseColorAndOpacity + (abcdefghijkl * x);
    return oC0;
}
