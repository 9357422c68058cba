// ps_3_0 shader decompiled by ps30
float3 L : register(c0);

float4 main(float4 normal0 : NORMAL0, float4 tangent0 : TANGENT0, float4 binormal0 : BINORMAL0, float4 color0 : COLOR0, float4 fog0 : FOG0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xyz = tangent0.xyz * 0.1 + normal0.xyz;
    r1.xyz = normalize((binormal0.xyz * 0.1 + r0.xyz));
    oC0 = (saturate(dot(r1.xyz, L)) * color0) * fog0.x;
    return oC0;
}
