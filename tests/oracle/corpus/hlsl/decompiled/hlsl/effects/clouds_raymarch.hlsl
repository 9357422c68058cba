// ps_3_0 shader decompiled by ps30
float3 camPos : register(c0);
float coverage : register(c2);
float densityScale : register(c3);
float2 slab : register(c1);
float3 sunDirW : register(c4);
sampler3D noiseVol : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    r1.xyz = normalize((texcoord0.xyz - camPos));
    r0.xy = slab - camPos.y;
    r0.z = 1.0 / r1.y;
    r0.x = r0.z * r0.x;
    r0.y = (r0.y * r0.z - r0.x) * 0.041666668;
    r2.w = 0.0;
    r3.w = 0.0;
    r0.zw = float2(1.0, 0.0);
    r1.w = 0.0;
    for (int n0 = 0; n0 < int4(24, 0, 0, 0).x; n0++) {
        r4.xyz = r1.xyz * (r0.y * (r1.w + 0.5) + r0.x) + camPos;
        r2.xyz = r4.xyz * 0.001;
        r5 = tex3Dlod(noiseVol, r2);
        r2.x = saturate(r5.x - coverage) * densityScale;
        r3.xyz = (sunDirW * 50.0 + r4.xyz) * 0.001;
        r4 = tex3Dlod(noiseVol, r3);
        r2.y = r0.z * r2.x;
        r2.z = exp2(((-r4.x * densityScale) * 1.442695));
        r2.y = r2.y * r2.z + r0.w;
        r2.x = (r0.y * -r2.x) * 1.442695;
        r2.x = r0.z * exp2(r2.x);
        if (r2.x < 0.01) {
            r0.zw = r2.xy;
            if (1.0 != -1.0) break;
        }
        r1.w = r1.w + 1.0;
        r0.zw = r2.xy;
    }
    oC0.xyz = r0.w;
    oC0.w = 1.0 - r0.z;
    return oC0;
}
