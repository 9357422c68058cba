// ps_3_0 shader decompiled by ps30
float HeightScale : register(c0);
float4 MaxSamples : register(c2); // the table's type: int
float4 MinSamples : register(c1); // the table's type: int
sampler2D HeightSampler : register(s0);
sampler2D AlbedoSampler : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0.xyz = normalize(texcoord1.xyz);
    r1.xy = ddx(texcoord0.xy);
    r1.zw = ddy(texcoord0.xy);
    r0.w = dot(r0.xyz, normalize(texcoord2.xyz));
    r2.x = MinSamples.x - MaxSamples.x;
    r2.y = abs(r0.w) * r2.x;
    r0.w = abs(r0.w) * r2.x + MaxSamples.x;
    r2.x = frac(r2.y);
    r2.y = r0.w - r2.x;
    r0.w = (r0.w >= 0.0 ? 0.0 : (-r2.x >= 0.0 ? 0.0 : 1.0)) + r2.y;
    r2.x = 1.0 / r0.w;
    r0.z = 1.0 / r0.z;
    r0.xy = (r0.z * -r0.xy) * HeightScale;
    r2.yz = texcoord0.xy;
    r3.xy = texcoord0.xy;
    r0.z = 1.0;
    r2.w = 1.0;
    r3.zw = float2(1.0, 0.0);
    for (int n0 = 0; n0 < int4(255, 0, 0, 0).x; n0++) {
        r4.x = r0.w;
        if (r3.w >= r4.x) break;
        r4 = tex2Dgrad(HeightSampler, r2.yz, r1.xy, r1.zw);
        if (r3.z < r4.x) {
            r0.z = r4.x;
            if (1.0 != -1.0) break;
        }
        r4.yz = r0.xy * r2.x + r2.yz;
        r3.z = r3.z - r2.x;
        r3.xy = r2.yz;
        r2.w = r4.x;
        r2.yz = r4.yz;
        r3.w = r3.w + 1.0;
        r0.z = r4.x;
    }
    r0.x = r0.z - r3.z;
    r0.y = (r2.w - r3.z) - r2.x;
    r0.y = 1.0 / (r0.x - r0.y);
    oC0 = tex2Dgrad(AlbedoSampler, lerp(r2.yz, r3.xy, (r0.y * r0.x)), r1.xy, r1.zw);
    return oC0;
}
