// ps_3_0 shader decompiled by ps30
float decay : register(c3);
float density : register(c1);
float exposure : register(c4);
float2 sunScreenPos : register(c0);
float weight : register(c2);
sampler2D occlusionMask : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.xy = (texcoord0.xy - sunScreenPos) * density;
    r0.zw = r0.xy * -0.041666668 + texcoord0.xy;
    r1.xy = r0.xy * -0.041666668 + r0.zw;
    r2 = tex2D(occlusionMask, r0.zw);
    r3 = tex2D(occlusionMask, r1.xy);
    r0.zw = r0.xy * -0.041666668 + r1.xy;
    r1.x = r2.x * weight + ((r3.x * decay) * weight);
    r1.y = decay * decay;
    [loop] for (int n0 = 0; n0 < 19; n0++) {
        r2 = tex2D(occlusionMask, r0.zw);
        r0.zw = r0.xy * -0.041666668 + r0.zw;
        r1.z = r1.y * r2.x;
        r1.y = r1.y * decay;
        r1.x = r1.z * weight + r1.x;
    }
    r2 = tex2D(occlusionMask, r0.zw);
    r0.zw = r0.xy * -0.041666668 + r0.zw;
    r3 = tex2D(occlusionMask, r0.zw);
    r0 = tex2D(occlusionMask, (r0.xy * -0.041666668 + r0.zw));
    r0.y = r1.y * r2.x;
    r0.z = r1.y * decay;
    r0.y = r0.y * weight + r1.x;
    r0.w = r0.z * r3.x;
    r0.z = r0.z * decay;
    r0.x = r0.z * r0.x;
    r0.y = r0.w * weight + r0.y;
    oC0 = (r0.x * weight + r0.y) * exposure;
    return oC0;
}
