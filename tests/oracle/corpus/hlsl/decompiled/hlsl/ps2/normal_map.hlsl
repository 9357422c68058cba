// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
float4 lightColor : register(c0);
float specPower : register(c1);
sampler2D diffuseMap : register(s0);
sampler2D normalMap : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r1 = tex2D(diffuseMap, texcoord0.xy);
    r2.xyz = normalize((tex2D(normalMap, texcoord0.xy).xyz * 2.0 - 1.0));
    r2.w = saturate(dot(r2.xyz, normalize(texcoord2.xyz)));
    r2.w = pow(abs(r2.w), specPower) * lightColor.w;
    r0.x = saturate(dot(r2.xyz, normalize(texcoord1.xyz)));
    r0.yzw = r1.zyx * lightColor.zyx;
    r1.xyz = r0.wzy * r0.x + r2.w;
    oC0 = r1;
    return oC0;
}
