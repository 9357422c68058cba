// ps_3_0 shader decompiled by ps30
float3 camPos : register(c0);
float3 etaRGB : register(c1);
samplerCUBE envCube : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    r0.xyz = etaRGB * etaRGB;
    r2.xyz = normalize((texcoord0.xyz - camPos));
    r1.xyz = normalize(texcoord1.xyz);
    r0.w = dot(r2.xyz, r1.xyz);
    r0.xyz = r0.xyz * -(r0.w * -r0.w + 1.0) + 1.0;
    r3.xyz = r0.xyz >= 0.0 ? 1.0 : 0.0;
    r0.xyz = r0.xyz * r3.xyz;
    r3.xyz = r3.xyz * etaRGB;
    r0.x = 1.0 / rsqrt(abs(r0.x));
    r4 = texCUBE(envCube, (r3.x * r2.xyz - (r1.xyz * (r3.x * r0.w + r0.x))));
    r0.x = rsqrt(abs(r0.y));
    r0.y = 1.0 / rsqrt(abs(r0.z));
    r3.xzw = r3.z * r2.xyz - (r1.xyz * (r3.z * r0.w + r0.y));
    r4.z = texCUBE(envCube, r3.xzw).z;
    r0.x = 1.0 / r0.x;
    r0.x = r3.y * r0.w + r0.x;
    r0.xyz = r3.y * r2.xyz - (r1.xyz * r0.x);
    r4.y = texCUBE(envCube, r0.xyz).y;
    r0.x = r0.w + r0.w;
    r0.y = r0.w + 1.0;
    r0.xzw = r1.xyz * -r0.x + r2.xyz;
    r0.xzw = -r4.xyz + texCUBE(envCube, r0.xzw).xyz;
    r0.y = saturate(r0.y * (r0.y * r0.y));
    oC0.xyz = r0.y * r0.xzw + r4.xyz;
    oC0.w = 1.0;
    return oC0;
}
