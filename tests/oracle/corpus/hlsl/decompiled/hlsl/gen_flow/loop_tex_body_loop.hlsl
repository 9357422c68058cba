// ps_3_0 shader decompiled by ps30
float2 d : register(c0);
sampler2D s : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = 0.0;
    r1.x = 0.0;
    for (int n0 = 0; n0 < int4(5, 0, 0, 0).x; n0++) {
        r1.yz = d * r1.x + texcoord0.xy;
        r2 = tex2D(s, r1.yz);
        r0 = r0 + r2;
        r1.x = r1.x + 1.0;
    }
    oC0 = r0;
    return oC0;
}
