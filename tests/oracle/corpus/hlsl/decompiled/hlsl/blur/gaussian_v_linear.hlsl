// ps_3_0 shader decompiled by ps30
float2 invSize : register(c0);
sampler2D blurSrc : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r1.xyz = float3(0.0, 1.3846154, 3.2307692);
    r2 = invSize.y * r1.xyxz + texcoord0.xyxy;
    r3 = tex2D(blurSrc, r2.xy);
    r0 = tex2D(blurSrc, texcoord0.xy) * 0.22702703 + (r3 * 0.31621623);
    r1 = invSize.y * -r1.xyxz + texcoord0.xyxy;
    r3 = tex2D(blurSrc, r1.xy);
    r0 = r3 * 0.31621623 + r0;
    oC0 = tex2D(blurSrc, r1.zw) * 0.07027027 + (tex2D(blurSrc, r2.zw) * 0.07027027 + r0);
    return oC0;
}
