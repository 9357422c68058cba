// ps_3_0 shader decompiled by ps30
float depth : register(c0);
float lodBias : register(c1);
sampler2D reliefMap : register(s0);
sampler2D texmap : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.xyz = normalize(texcoord1.xyz);
    r0.xy = r0.xy * depth;
    r0.z = 1.0 / r0.z;
    r0.xy = r0.z * r0.xy;
    r1.xy = float2(0.0, 1.0);
    r2.zw = r1.xy * lodBias;
    r0.zw = float2(0.0, 1.0);
    for (int n0 = 0; n0 < int4(9, 0, 0, 0).x; n0++) {
        r0.z = r0.z + 0.1;
        r2.xy = r0.xy * r0.z + texcoord0.xy;
        r3 = tex2Dlod(reliefMap, r2);
        r1.z = 0.996 - r0.w;
        r1.w = (r0.z - r3.w) >= 0.0 ? -1.0 : -0.0;
        r1.z = r1.z >= 0.0 ? 0.0 : r1.w;
        r0.w = r1.z >= 0.0 ? r0.w : r0.z;
    }
    r1.zw = r1.xy * lodBias;
    r2.xz = r0.w;
    r0.z = 0.1;
    for (int n0 = 0; n0 < int4(5, 0, 0, 0).x; n0++) {
        r2.w = r0.z * 0.5;
        r1.xy = r0.xy * r2.z + texcoord0.xy;
        r3 = tex2Dlod(reliefMap, r1);
        r1.x = r2.z - r3.w;
        r2.y = r2.z - r0.z;
        r2.xy = r1.x >= 0.0 ? r2.zy : r2.xz;
        r2.z = r0.z * 0.5 + r2.y;
        r0.z = r2.w;
    }
    oC0 = tex2D(texmap, (r0.xy * r2.x + texcoord0.xy));
    return oC0;
}
