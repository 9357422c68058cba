// ps_3_0 shader decompiled by ps30
float irisDepth : register(c1);
float irisRadius : register(c0);
float3 lightT : register(c2);
sampler2D irisTex : register(s0);
sampler2D scleraTex : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0.xy = texcoord0.xy - 0.5;
    r0.x = dot(r0.xy, r0.xy) + 0.0;
    r0.x = 1.0 / rsqrt(abs(r0.x));
    r0.y = r0.x * r0.x;
    r0.z = 1.0 / (irisRadius * irisRadius);
    r0.y = (r0.y * -r0.z + 1.0) * irisDepth;
    r1.xyz = normalize(texcoord1.xyz);
    r0.zw = (1.0 / r1.z) * r1.xy;
    r0.yz = r0.y * r0.zw;
    r0.w = 0.01 + irisRadius;
    r0.x = saturate((r0.x - r0.w) * -50.0);
    r0.w = r0.x * -2.0 + 3.0;
    r0.x = r0.x * r0.x;
    r0.x = r0.x * r0.w;
    r0.yz = r0.yz * -r0.x + texcoord0.xy;
    r0.w = 1.0 / (irisRadius + irisRadius);
    r4 = lerp(tex2D(scleraTex, texcoord0.xy), tex2D(irisTex, lerp(0.5, r0.yz, r0.w)), r0.x);
    r2.xyz = normalize((texcoord0.xyx * float3(2.0, 2.0, 0.0) + float3(-1.0, -1.0, 1.0)));
    r0.xyz = normalize(lightT);
    r0.w = dot(-r0.xyz, r2.xyz);
    r0.w = r0.w + r0.w;
    r0.x = saturate(dot((r2.xyz * -r0.w - r0.xyz), r1.xyz));
    oC0 = pow(abs(r0.x), 200.0) + r4;
    return oC0;
}
