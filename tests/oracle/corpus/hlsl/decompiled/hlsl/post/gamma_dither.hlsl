// ps_3_0 shader decompiled by ps30
float invGamma : register(c0);
sampler2D linearScene : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float2 vpos : VPOS) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xy = frac(abs((0.25 * vpos)));
    r0.xy = vpos >= 0.0 ? r0.xy : -r0.xy;
    r0.zw = r0.xy * 4.0;
    r1.xy = frac(r0.zw);
    r0.zw = r0.zw - r1.xy;
    r0.xy = r0.xy >= 0.0 ? 0.0 : (-r1.xy >= 0.0 ? 0.0 : 1.0);
    r0.xy = r0.xy + r0.zw;
    r0.x = r0.y * 4.0 + r0.x;
    r1 = r0.x + float4(-1.0, -2.0, -3.0, -4.0);
    r0.y = -abs(r1.y) >= 0.0 ? -0.0013480393 : (-abs(r1.x) >= 0.0 ? 0.00012254903 : -0.0018382354);
    r0.y = -abs(r1.w) >= 0.0 ? 0.0011029412 : (-abs(r1.z) >= 0.0 ? 0.0006127451 : r0.y);
    r1 = r0.x + float4(-5.0, -6.0, -7.0, -8.0);
    r0.y = -abs(r1.y) >= 0.0 ? 0.0015931374 : (-abs(r1.x) >= 0.0 ? -0.0008578432 : r0.y);
    r0.y = -abs(r1.w) >= 0.0 ? -0.0011029412 : (-abs(r1.z) >= 0.0 ? -0.0003676471 : r0.y);
    r1 = r0.x + float4(-9.0, -10.0, -11.0, -12.0);
    r0.xzw = r0.x + float3(-13.0, -14.0, -15.0);
    r0.y = -abs(r1.y) >= 0.0 ? -0.0015931374 : (-abs(r1.x) >= 0.0 ? 0.0008578432 : r0.y);
    r0.y = -abs(r1.w) >= 0.0 ? 0.0018382354 : (-abs(r1.z) >= 0.0 ? 0.0003676471 : r0.y);
    r0.x = -abs(r0.x) >= 0.0 ? -0.00012254903 : r0.y;
    r0.x = -abs(r0.z) >= 0.0 ? 0.0013480393 : r0.x;
    r0.x = -abs(r0.w) >= 0.0 ? -0.0006127451 : r0.x;
    r1 = tex2D(linearScene, texcoord0.xy);
    r2.x = log2(abs(r1.x));
    r2.y = log2(abs(r1.y));
    r2.z = log2(abs(r1.z));
    r0.yzw = r2.xyz * invGamma;
    r1.x = exp2(r0.y);
    r1.y = exp2(r0.z);
    r1.z = exp2(r0.w);
    oC0.xyz = r0.x + r1.xyz;
    oC0.w = 1.0;
    return oC0;
}
