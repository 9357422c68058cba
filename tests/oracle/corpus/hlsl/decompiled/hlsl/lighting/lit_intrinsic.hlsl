// ps_3_0 shader decompiled by ps30
float4 LightDirection : register(c0);
float4 MaterialDiffuse : register(c1);
float4 MaterialSpecular : register(c2);
float Shininess : register(c3);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r1.xyz = normalize(texcoord0.xyz);
    r0.x = dot(r1.xyz, normalize(texcoord1.xyz));
    r0.y = dot(r1.xyz, LightDirection.xyz);
    r0.z = -r0.y >= 0.0 ? 0.0 : 1.0;
    r0.y = r0.y * r0.z;
    r0.x = (-r0.x >= 0.0 ? 0.0 : r0.z) * pow(abs(r0.x), Shininess);
    oC0 = MaterialDiffuse * r0.y + (r0.x * MaterialSpecular);
    return oC0;
}
