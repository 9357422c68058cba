// ps_3_0 shader decompiled by ps30
float depthScale : register(c0);
float3 lightTS : register(c1);
sampler2D hgt : register(s0);
sampler2D col : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0, r6 = 0;
    r0.xy = rsqrt(abs(dot(texcoord1.xyz, texcoord1.xyz))) * texcoord1.xy;
    r0.xy = (-r0.xy * depthScale) * 0.0625;
    r0.zw = ddx(texcoord0.xy);
    r1.xy = ddy(texcoord0.xy);
    r2 = tex2Dgrad(hgt, texcoord0.xy, r0.zw, r1.xy);
    r1.zw = -(1.0 - r2.x) >= 0.0 ? 0.0 : float2(1.0, 0.0625);
    r2.xy = r0.xy * r1.z + texcoord0.xy;
    r3 = tex2Dgrad(hgt, r2.xy, r0.zw, r1.xy);
    r1.z = 1.0 - r3.x;
    r2.zw = (r1.w - r1.z) >= 0.0 ? 0.0 : float2(1.0, 0.0625);
    r2.xy = r0.xy * r2.z + r2.xy;
    r1.z = r1.w + r2.w;
    [loop] for (int n0 = 0; n0 < 13; n0++) {
        r3 = tex2Dgrad(hgt, r2.xy, r0.zw, r1.xy);
        r1.w = 1.0 - r3.x;
        r1.w = r1.z - r1.w;
        r2.zw = r1.w >= 0.0 ? 0.0 : float2(1.0, 0.0625);
        r2.xy = r0.xy * r2.z + r2.xy;
        r1.z = r1.z + r2.w;
    }
    r1.w = 1.0 - (tex2Dgrad(hgt, r2.xy, r0.zw, r1.xy).x);
    r1.z = r1.z - r1.w;
    r0.xy = r0.xy * (r1.z >= 0.0 ? 0.0 : 1.0) + r2.xy;
    r2 = (rsqrt(abs(dot(lightTS, lightTS))) * lightTS.xyxy) * depthScale;
    r3 = r2.zwzw * float4(0.125, 0.125, 0.25, 0.25) + r0.xyxy;
    r2 = r2 * float4(0.375, 0.375, 0.5, 0.5) + r0.xyxy;
    r4 = tex2Dgrad(hgt, r3.xy, r0.zw, r1.xy);
    r3 = tex2Dgrad(hgt, r3.zw, r0.zw, r1.xy);
    r5 = tex2Dgrad(hgt, r0.xy, r0.zw, r1.xy);
    r6 = tex2Dgrad(col, r0.xy, r0.zw, r1.xy);
    r0.x = 1.0 - (1.0 - r5.x);
    r0.y = r4.x - r0.x;
    r0.y = saturate((r0.y - 0.125) * 8.0);
    r1.z = saturate(((r3.x - r0.x) - 0.25) * 8.0);
    r3.x = min((1.0 - r1.z), (1.0 - r0.y));
    r4 = tex2Dgrad(hgt, r2.xy, r0.zw, r1.xy);
    r0.y = -r0.x + tex2Dgrad(hgt, r2.zw, r0.zw, r1.xy).x;
    r0.x = r4.x - r0.x;
    r0.x = saturate((r0.x - 0.375) * 8.0);
    r1.x = min((1.0 - r0.x), r3.x);
    r0.x = saturate((r0.y - 0.5) * 8.0);
    r2.x = min((1.0 - r0.x), r1.x);
    oC0 = (r2.x * 0.6 + 0.4) * r6;
    return oC0;
}
