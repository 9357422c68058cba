// ps_3_0 shader decompiled by ps30
float4 eyePos : register(c1);
float4 lightPos : register(c0);
float4 matDiffuse : register(c2);
float4 matSpecular : register(c3);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r1.xyz = normalize((eyePos.xyz - texcoord0.xyz));
    r2.xyz = normalize((lightPos.xyz - texcoord0.xyz));
    r0.xyz = normalize(texcoord1.xyz);
    r0.w = dot(-r2.xyz, r0.xyz);
    r0.w = r0.w + r0.w;
    r3.xyz = r0.xyz * -r0.w - r2.xyz;
    r0.x = saturate(dot(r0.xyz, r2.xyz));
    r0.y = saturate(dot(r3.xyz, r1.xyz));
    r1.xyz = pow(abs(r0.y), matSpecular.w) * matSpecular.xyz;
    r1.w = 0.0;
    oC0 = matDiffuse * r0.x + r1;
    return oC0;
}
