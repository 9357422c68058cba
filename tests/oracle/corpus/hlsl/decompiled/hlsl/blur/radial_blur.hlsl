// ps_3_0 shader decompiled by ps30
float2 center : register(c0);
float strength : register(c1);
sampler2D sceneSampler : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xy = ((center - texcoord0.xy) * strength) * 0.083333336;
    r1 = 0.0;
    r0.zw = float2(1.0, 0.0);
    for (int n0 = 0; n0 < int4(12, 0, 0, 0).x; n0++) {
        r2 = tex2D(sceneSampler, (r0.xy * r0.w + texcoord0.xy));
        r1 = r2 * r0.z + r1;
        r0.z = r0.z * 0.92;
        r0.w = r0.w + 1.0;
    }
    oC0 = r1 * 0.12651548;
    return oC0;
}
