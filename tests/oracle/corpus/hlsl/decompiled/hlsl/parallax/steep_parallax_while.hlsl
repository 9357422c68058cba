// ps_3_0 shader decompiled by ps30
float scale : register(c0);
sampler2D heightTex : register(s0);
sampler2D albedoTex : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.xyz = normalize(texcoord1.xyz);
    r0.z = 1.0 / (abs(r0.z) * -16.0 + 24.0);
    r0.xy = r0.xy * scale;
    r0.w = 1.0 - (tex2Dlod(heightTex, (float4(1.0, 1.0, 0.0, 0.0) * texcoord0.xyxx)).x);
    r1.zw = 0.0;
    r1.xy = texcoord0.xy;
    r2.x = 0.0;
    r2.y = r0.w;
    for (int n0 = 0; n0 < int4(32, 0, 0, 0).x; n0++) {
        if (r2.x >= r2.y) break;
        r1.xy = r0.xy * -r0.z + r1.xy;
        r3 = tex2Dlod(heightTex, r1);
        r2.y = 1.0 - r3.x;
        r2.x = r0.z + r2.x;
    }
    oC0 = tex2D(albedoTex, r1.xy);
    return oC0;
}
