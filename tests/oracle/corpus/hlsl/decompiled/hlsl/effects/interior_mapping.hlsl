// ps_3_0 shader decompiled by ps30
float3 roomScale : register(c0);
samplerCUBE roomCube : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = frac((roomScale * texcoord0.xyz)) * 2.0 - 1.0;
    r1.xyz = normalize(texcoord1.xyz);
    r2.x = 1.0 / r1.x;
    r2.y = 1.0 / r1.y;
    r2.z = 1.0 / r1.z;
    r2.xyz = r0.xyz * -r2.xyz + abs(r2.xyz);
    r1.w = min(r2.z, min(r2.y, r2.x));
    oC0 = texCUBE(roomCube, (r1.xyz * r1.w + r0.xyz));
    return oC0;
}
