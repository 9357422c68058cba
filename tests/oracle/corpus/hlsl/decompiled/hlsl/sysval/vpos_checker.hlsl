// ps_3_0 shader decompiled by ps30
float cell : register(c1);
float2 invRes : register(c0);
sampler2D scene : register(s0);

float4 main(float2 vpos : VPOS) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xy = (1.0 / cell) * vpos;
    r0.zw = frac(r0.xy);
    r0.xy = r0.xy - r0.zw;
    r0.x = r0.y + r0.x;
    r0.x = frac((r0.x * 0.5));
    r1 = tex2D(scene, ((0.5 + vpos) * invRes));
    oC0 = (r0.x * 2.0 - r1) * 0.25 + r1;
    return oC0;
}
