// ps_3_0 shader decompiled by ps30
float lightSizeUV : register(c0);
float nearPlane : register(c1);
sampler2D shadowDepth : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    r0.x = 1.0 / texcoord0.w;
    r0.yzw = r0.x * texcoord0.xyz;
    r1.x = (texcoord0.z * r0.x - nearPlane) * lightSizeUV;
    r1.y = 1.0 / r0.w;
    r1.x = r1.y * r1.x;
    r2.zw = 0.0;
    r1.yzw = 0.0;
    for (int n0 = 0; n0 < int4(8, 0, 0, 0).x; n0++) {
        r3 = r1.w + float4(-0.0, -1.0, -2.0, -3.0);
        r4 = r1.w + float4(-4.0, -5.0, -6.0, -7.0);
        r5.xy = -abs(r3.x) >= 0.0 ? float2(-0.7071, 0.7071) : 0.0;
        r3.xy = -abs(r3.y) >= 0.0 ? float2(0.0, -0.875) : r5.xy;
        r3.xy = -abs(r3.z) >= 0.0 ? 0.5303 : r3.xy;
        r3.xy = -abs(r4.x) >= 0.0 ? float2(0.3536, -0.3536) : (-abs(r3.w) >= 0.0 ? float2(-0.625, 0.0) : r3.xy);
        r3.xy = -abs(r4.z) >= 0.0 ? -0.1768 : (-abs(r4.y) >= 0.0 ? float2(0.0, 0.375) : r3.xy);
        r2.xy = (-abs(r4.w) >= 0.0 ? float2(0.125, 0.0) : r3.xy) * r1.x + r0.yz;
        r3 = tex2Dlod(shadowDepth, r2);
        r2.x = texcoord0.z * -r0.x + r3.x;
        r3.x = r1.y + r3.x;
        r3.y = r1.z + 1.0;
        r1.yz = r2.x >= 0.0 ? r1.yz : r3.xy;
        r1.w = r1.w + 1.0;
    }
    if (-r1.z >= 0.0) {
        oC0 = 1.0;
    } else {
        r1.x = 1.0 / r1.z;
        r1.x = r1.x * r1.y;
        r1.y = texcoord0.z * r0.x - r1.x;
        r1.y = (r1.y * lightSizeUV) * nearPlane;
        r0.w = r0.w * r1.x;
        r0.w = (1.0 / r0.w) * r1.y;
        r1.zw = 0.0;
        r2.xy = 0.0;
        for (int n0 = 0; n0 < int4(8, 0, 0, 0).x; n0++) {
            r3 = r2.y + float4(-0.0, -1.0, -2.0, -3.0);
            r4 = r2.y + float4(-4.0, -5.0, -6.0, -7.0);
            r2.zw = -abs(r3.y) >= 0.0 ? float2(0.0, -0.875) : (-abs(r3.x) >= 0.0 ? float2(-0.7071, 0.7071) : 0.0);
            r2.zw = -abs(r3.w) >= 0.0 ? float2(-0.625, 0.0) : (-abs(r3.z) >= 0.0 ? 0.5303 : r2.zw);
            r2.zw = -abs(r4.y) >= 0.0 ? float2(0.0, 0.375) : (-abs(r4.x) >= 0.0 ? float2(0.3536, -0.3536) : r2.zw);
            r2.zw = -abs(r4.w) >= 0.0 ? float2(0.125, 0.0) : (-abs(r4.z) >= 0.0 ? -0.1768 : r2.zw);
            r1.xy = r2.zw * r0.w + r0.yz;
            r3 = tex2Dlod(shadowDepth, r1);
            r1.x = (texcoord0.z * -r0.x + r3.x) >= 0.0 ? 1.0 : 0.0;
            r2.x = r1.x + r2.x;
            r2.y = r2.y + 1.0;
        }
        oC0 = r2.x * 0.125;
    }
    return oC0;
}
