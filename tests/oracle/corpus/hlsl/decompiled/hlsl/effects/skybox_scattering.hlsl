// ps_3_0 shader decompiled by ps30
float mieG : register(c2);
float nightAmount : register(c3);
float3 rayleighColor : register(c1);
float3 sunDirection : register(c0);
samplerCUBE stars : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xz = float2(1.0, 2.0);
    r0.y = mieG * -mieG + r0.x;
    r0.zw = mieG * mieG + r0.zx;
    r0.z = 1.0 / r0.z;
    r0.y = r0.z * r0.y;
    r1.xyz = normalize(texcoord0.xyz);
    r0.z = dot(r1.xyz, sunDirection);
    r1.w = r0.z * r0.z + 1.0;
    r0.y = r0.y * r1.w;
    r2.xyz = (r1.w * 0.75) * rayleighColor;
    r0.y = r0.y * 1.5;
    r0.w = dot(r0.zz, -mieG.xx) + r0.w;
    r0.z = saturate((r0.z - 0.9995) * 3332.7803);
    r0.w = 1.0 / pow(abs(r0.w), 1.5);
    r0.y = (r0.w * r0.y) * 0.02;
    r0.w = saturate(r1.y);
    r0.w = 1.0 - r0.w;
    r0.w = r0.w * r0.w;
    r0.w = r0.w * r0.w + 1.0;
    r2.xyz = r2.xyz * r0.w + r0.y;
    r0.x = r0.x - nightAmount;
    r0.y = r0.z * -2.0 + 3.0;
    r0.z = r0.z * r0.z;
    r0.y = (r0.z * r0.y) * 20.0;
    oC0.xyz = texCUBE(stars, r1.xyz).xyz * nightAmount + (r2.xyz * r0.x + r0.y);
    oC0.w = 1.0;
    return oC0;
}
