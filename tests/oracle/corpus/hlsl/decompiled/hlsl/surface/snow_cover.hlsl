// ps_3_0 shader decompiled by ps30
float snowAmount : register(c0);
float3 upWS : register(c1);
sampler2D baseTex : register(s0);
sampler2D snowTex : register(s1);
sampler2D normTex : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = tex2D(normTex, texcoord0.xy).xyz - 0.5;
    r0.x = dot(normalize((r0.xyz * 0.3 + texcoord1.xyz)), upWS);
    r0.y = 1.0 - snowAmount;
    r0.x = saturate((r0.x - r0.y) * 10.0);
    r0.y = r0.x * -2.0 + 3.0;
    r0.x = r0.x * r0.x;
    r0.x = r0.x * r0.y;
    r2 = tex2D(baseTex, texcoord0.xy);
    oC0 = r0.x * (tex2D(snowTex, (3.0 * texcoord0.xy)) - r2) + r2;
    return oC0;
}
