// ps_3_0 shader decompiled by ps30
float4 fogColor : register(c0);
float fogEnd : register(c2);
float fogStart : register(c1);
sampler2D texDiffuse : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = 1.0 / (fogEnd - fogStart);
    r0.y = fogEnd - texcoord1.x;
    r0.x = saturate(r0.x * r0.y);
    r1 = tex2D(texDiffuse, texcoord0.xy);
    r0.yzw = r1.xyz - fogColor.xyz;
    oC0.w = r1.w;
    oC0.xyz = r0.x * r0.yzw + fogColor.xyz;
    return oC0;
}
