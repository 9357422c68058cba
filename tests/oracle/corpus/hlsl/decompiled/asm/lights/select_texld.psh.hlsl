// ps_3_0 shader decompiled by ps30
float4 c4 : register(c4);
sampler2D s0 : register(s0);
sampler2D s1 : register(s1);
sampler2D s2 : register(s2);
sampler2D s3 : register(s3);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0 = tex2D(s0, texcoord0.xy);
    r1.xy = texcoord0.xy * c4.xy;
    r1.zw = 0.0;
    r2.x = dot(r0.xyz, float3(0.48, 0.6, 0.64));
    if (r0.w < 0.99999) {
        r3 = tex2D(s1, r1.xy);
        r2.x = max(r2.x, 0.0);
        r4.xyz = r3.xyz * r2.x;
    } else {
        if (r0.w < 1.99999) {
            r3 = tex2D(s2, r1.xy);
            r2.x = saturate(r2.x * 0.6666667 + 0.3333333);
            r4.xyz = r3.xyz * r2.x;
        } else {
            r3 = tex2D(s3, r1.xy);
            r2.y = dot(r0.xyz, float3(0.26504, 0.3313, 0.90554));
            r2.xy = max(r2.xy, 0.0);
            [loop] for (int n0 = 0; n0 < 4; n0++) {
                r2.y = r2.y * r2.y;
            }
            r2.y = r2.y * r3.w;
            r4.xyz = r3.xyz * r2.x + r2.y;
        }
    }
    r4.w = 1.0;
    oC0 = r4;
    return oC0;
}
