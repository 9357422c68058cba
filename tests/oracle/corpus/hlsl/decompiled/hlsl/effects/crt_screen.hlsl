// ps_3_0 shader decompiled by ps30
float curvature : register(c1);
float2 srcSize : register(c0);
sampler2D frameBuf : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float2 vpos : VPOS) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xy = float2(1.0, 2.0) + vpos.x;
    r0.zw = frac(abs((r0.xy * 0.33333334)));
    r0.xy = r0.xy >= 0.0 ? r0.zw : -r0.zw;
    r0.yz = (r0.xy - 0.33333334) >= 0.0 ? 0.0 : 1.0;
    r0.w = frac(abs((0.33333334 * vpos.x)));
    r0.w = vpos.x >= 0.0 ? r0.w : -r0.w;
    r0.x = (r0.w - 0.33333334) >= 0.0 ? 0.0 : 1.0;
    r0.xyz = r0.xyz * 0.5 + 0.5;
    r1.xy = texcoord0.xy * 2.0 - 1.0;
    r0.w = dot(r1.xy, r1.xy) + 0.0;
    r1.xy = (r0.w * curvature + 1.0) * r1.xy;
    r1.zw = r1.xy * 0.5 + 0.5;
    r0.w = (dot(r1.xy, r1.xy) + 0.0) * -0.2 + 1.0;
    r1.x = 0.5;
    r1.x = frac((r1.w * srcSize.y + r1.x));
    r1.x = sin((r1.x * 6.2831855 - 3.1415927)) * 0.25 + 0.75;
    r0.xyz = r0.xyz * (r1.x * tex2D(frameBuf, r1.zw).xyz);
    r0.xyz = r0.w * r0.xyz;
    r1.xy = 1.0 - r1.zw;
    r1 = r1 >= 0.0 ? 0.0 : 1.0;
    r0.w = dot(r1.zw, r1.zw) + 0.0;
    r1.x = dot(r1.xy, r1.xy) + 0.0;
    r0.w = (-r0.w >= 0.0 ? 0.0 : 1.0) + (-r1.x >= 0.0 ? 0.0 : 1.0);
    oC0.xyz = -r0.w >= 0.0 ? r0.xyz : 0.0;
    oC0.w = 1.0;
    return oC0;
}
