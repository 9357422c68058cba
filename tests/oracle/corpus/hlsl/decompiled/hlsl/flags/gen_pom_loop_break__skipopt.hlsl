// ps_3_0 shader decompiled by ps30
float HeightScale : register(c0);
float4 MaxSamples : register(c2); // the table's type: int
float4 MinSamples : register(c1); // the table's type: int
sampler2D HeightSampler : register(s0);
sampler2D AlbedoSampler : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0, r6 = 0;
    r0.xyz = rsqrt(abs(dot(texcoord1.xyz, texcoord1.xyz))) * texcoord1.xyz;
    r1.xy = ddx(texcoord0.xy);
    r1.zw = ddy(texcoord0.xy);
    r2.xyz = rsqrt(abs(dot(texcoord2.xyz, texcoord2.xyz))) * texcoord2.xyz;
    r0.w = abs(dot(r0.xyz, r2.xyz));
    r0.w = (r0.w * ((-MaxSamples.x) + MinSamples.x)) + MaxSamples.x;
    r2.x = frac(r0.w);
    r2.y = r0.w + (-r2.x);
    r2.z = -r0.w;
    r0.w = (r0.w + (-r2.z)) >= 0.0 ? 0.0 : 1.0;
    r2.z = -r2.x;
    r2.x = -r2.x;
    r2.x = r2.x + r2.z;
    r0.w = (r0.w * (r2.x >= 0.0 ? 0.0 : 1.0)) + r2.y;
    r2.x = (1.0 / r0.w) * 1.0;
    r3.x = 1.0 / r0.z;
    r3.y = 1.0 / r0.z;
    r0.xy = (-r0.xy) * r3.xy;
    r0.xy = r2.x * (r0.xy * HeightScale);
    r0.z = 1.0;
    r2.y = 1.0;
    r2.z = 1.0;
    r3.xy = texcoord0.xy;
    r3.zw = texcoord0.xy;
    r2.w = 0.0;
    r4.xy = r3.xy;
    r4.zw = r3.zw;
    r5.x = r0.z;
    r5.y = r2.y;
    r5.z = r2.z;
    r5.w = r2.w;
    for (int n0 = 0; n0 < int4(255, 0, 0, 0).x; n0++) {
        r6.x = (r5.w + (-r0.w)) >= 0.0 ? 0.0 : 1.0;
        r6.y = -r6.x;
        r6.x = -r6.x;
        r6.x = (r6.x + r6.y) >= 0.0 ? 1.0 : 0.0;
        if (r6.x != -r6.x) break;
        r6 = tex2Dgrad(HeightSampler, r4.xy, r1.xy, r1.zw);
        r6.x = r6.x;
        r6.y = -r6.x;
        r6.y = (r5.z + r6.y) >= 0.0 ? 0.0 : 1.0;
        if (r6.y != -r6.y) {
            r5.x = r6.x;
            if (1.0 != -1.0) break;
        }
        r4.zw = r4.xy;
        r5.y = r6.x;
        r4.xy = r0.xy + r4.xy;
        r6.y = -r2.x;
        r5.z = r5.z + r6.y;
        r5.w = r5.w + 1.0;
        r5.x = r6.x;
    }
    r0.x = (-r5.z) + r5.x;
    r0.y = (-r5.z) + r5.y;
    r0.z = -r2.x;
    r0.y = -(r0.z + r0.y);
    r0.y = 1.0 / (r0.y + r0.x);
    r0.x = r0.y * r0.x;
    r0.yz = (-r4.xy) + r4.zw;
    r0.xy = r0.yz * r0.x;
    oC0 = tex2Dgrad(AlbedoSampler, (r0.xy + r4.xy), r1.xy, r1.zw);
    return oC0;
}
