// ps_3_0 shader decompiled by ps30
float3 eyeVec : register(c1);
float3 lightVec : register(c0);
float primaryShift : register(c2);
float specExp1 : register(c3);
float specExp2 : register(c4);
sampler2D hairDiffuse : register(s0);
sampler2D hairShift : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.x = tex2D(hairShift, texcoord0.xy).x - 0.5;
    r0.y = -2.0;
    r0.y = primaryShift * r0.y + r0.x;
    r0.x = r0.x + primaryShift;
    r1.xyz = texcoord2.xyz;
    r2.xyz = normalize((r1.xyz * r0.x + texcoord1.xyz));
    r1.xyz = normalize((r1.xyz * r0.y + texcoord1.xyz));
    r3.xyz = normalize((lightVec + eyeVec));
    r0.x = dot(r1.xyz, r3.xyz);
    r0.y = dot(r2.xyz, r3.xyz);
    r0.z = saturate(r0.x + 1.0);
    r0.x = rsqrt(abs((r0.x * -r0.x + 1.0)));
    r1.x = pow(abs((1.0 / r0.x)), specExp2);
    r0.x = r0.z * -2.0 + 3.0;
    r0.z = r0.z * r0.z;
    r0.x = r0.z * r0.x;
    r0.x = (r1.x * r0.x) * 0.5;
    r0.z = saturate(r0.y + 1.0);
    r0.y = rsqrt(abs((r0.y * -r0.y + 1.0)));
    r1.x = pow(abs((1.0 / r0.y)), specExp1);
    r0.y = r0.z * -2.0 + 3.0;
    r0.z = r0.z * r0.z;
    r0.y = r0.z * r0.y;
    r0.x = r0.y * r1.x + r0.x;
    r0.y = saturate(dot(texcoord2.xyz, lightVec));
    r1 = tex2D(hairDiffuse, texcoord0.xy);
    oC0.xyz = r1.xyz * r0.y + r0.x;
    oC0.w = r1.w;
    return oC0;
}
