// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = frac(texcoord1.x);
    r0.y = -r0.x >= 0.0 ? 0.0 : 1.0;
    r0.x = texcoord1.x - r0.x;
    r0.y = texcoord1.x >= 0.0 ? 0.0 : r0.y;
    r0 = (r0.y + r0.x) + float4(-0.0, -1.0, -2.0, -3.0);
    r1.xyz = -abs(r0.y) >= 0.0 ? float3(0.0, 1.0, 0.0) : (-abs(r0.x) >= 0.0 ? float3(1.0, 0.0, 0.0) : 0.0);
    r0.xyz = -abs(r0.z) >= 0.0 ? float3(0.5, 1.0, 3.0) : (r1.xyz + float3(0.5, 1.0, 2.0));
    oC0.xyz = -abs(r0.w) >= 0.0 ? float3(1.5, 2.0, 2.0) : r0.xyz;
    oC0.w = 0.875;
    return oC0;
}
