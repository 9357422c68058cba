// ps_3_0 shader decompiled by ps30
float3 lightDirWS : register(c0);
float4 rimColor : register(c2);
float3 viewPos : register(c1);
sampler2D rampTex : register(s0);
sampler2D colorTex : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r1.xyz = normalize((viewPos - texcoord1.xyz));
    r0.xyz = normalize(texcoord2.xyz);
    r0.w = saturate(dot(r0.xyz, r1.xyz));
    r0.x = dot(r0.xyz, lightDirWS);
    r1 = tex2D(rampTex, (r0.x * 0.5 + 0.5).xx);
    r0.x = 0.3 - r0.w;
    r0.yzw = rimColor.w * rimColor.xyz;
    oC0.xyz = tex2D(colorTex, texcoord0.xy).xyz * r1.xyz + (r0.x >= 0.0 ? r0.yzw : 0.0);
    oC0.w = 1.0;
    return oC0;
}
