// ps_3_0 shader decompiled by ps30
float4 edgeColor : register(c1);
float2 texel : register(c0);
float threshold : register(c2);
sampler2D normalDepth : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0, r6 = 0;
    r0 = tex2D(normalDepth, (texcoord0.xy - texel));
    r1.xyz = float3(0.0, -1.0, 1.0);
    r2 = texel.xyxy * r1.xyzy + texcoord0.xyxy;
    r3 = tex2D(normalDepth, r2.xy);
    r2 = tex2D(normalDepth, r2.zw);
    r3 = r3 * -2.0 - r0;
    r0 = r2 - r0;
    r2 = r3 - r2;
    r3 = texel.xyxy * r1.yzxz + texcoord0.xyxy;
    r4 = tex2D(normalDepth, r3.xy);
    r2 = tex2D(normalDepth, r3.zw) * 2.0 + (r2 + r4);
    r3 = tex2D(normalDepth, (texel + texcoord0.xy));
    r2 = r2 + r3;
    r2.y = 1.0 / rsqrt(abs(dot(r2, r2)));
    r5 = texel.xyxy * r1.yxzx + texcoord0.xyxy;
    r6 = tex2D(normalDepth, r5.xy);
    r0 = tex2D(normalDepth, r5.zw) * 2.0 + (r6 * -2.0 + r0);
    r0 = r3 + (r0 - r4);
    r0.x = dot(r0, r0);
    r2.x = 1.0 / rsqrt(abs(r0.x));
    r0.x = 1.0 / rsqrt(abs((dot(r2.xy, r2.xy) + 0.0)));
    oC0 = (r0.x - threshold) >= 0.0 ? edgeColor : r1.x;
    return oC0;
}
