// ps_3_0 shader decompiled by ps30
float3 eyePos : register(c3);
float flakeScale : register(c2);
float4 paintColorEdge : register(c1);
float4 paintColorMid : register(c0);
sampler2D flakeNormals : register(s0);
samplerCUBE envMap : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.xyz = tex2D(flakeNormals, (flakeScale * texcoord0.xy)).xyz * 2.0 - 1.0;
    r1.xyz = normalize(texcoord2.xyz);
    r2.xyz = normalize((r0.xyz * 0.2 + r1.xyz));
    r3.xyz = normalize((eyePos - texcoord1.xyz));
    r1.w = pow(abs(saturate(dot(r2.xyz, r3.xyz))), 32.0);
    r0.xyz = paintColorMid.xyz - paintColorEdge.xyz;
    r0.w = saturate(dot(r1.xyz, r3.xyz));
    r2.x = r0.w * r0.w;
    r0.w = 1.0 - r0.w;
    r0.xyz = r1.w * 0.5 + (r2.x * r0.xyz + paintColorEdge.xyz);
    r1.w = dot(-r3.xyz, r1.xyz);
    r1.w = r1.w + r1.w;
    r1 = texCUBE(envMap, (r1.xyz * -r1.w - r3.xyz));
    r1.w = r0.w * r0.w;
    r0.w = (r0.w * (r1.w * r1.w)) * 0.96 + 0.04;
    oC0.xyz = r1.xyz * r0.w + r0.xyz;
    oC0.w = 1.0;
    return oC0;
}
