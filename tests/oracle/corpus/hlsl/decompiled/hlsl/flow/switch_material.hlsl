// ps_3_0 shader decompiled by ps30
float4 tints[4] : register(c0);
sampler2D t0 : register(s0);
sampler2D t1 : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.x = abs(texcoord1.x) - frac(abs(texcoord1.x));
    if (-r0.x >= 0.0) {
        oC0 = tex2D(t0, texcoord0.xy);
    } else {
        if (r0.x == 1.0) {
            oC0 = tex2D(t1, texcoord0.xy);
        } else {
            if (r0.x == 2.0) {
                r1 = tex2D(t0, texcoord0.xy);
                r2 = tex2D(t1, texcoord0.xy);
                oC0 = r1 * r2;
            } else {
                r0 = r0.x + float4(-0.0, -1.0, -2.0, -3.0);
                r0 = r0.w >= 0.0 ? float4(-3.0, -2.0, -1.0, -0.0) : -abs(r0);
                r1 = r0.x >= 0.0 ? tints[0] : 0.0;
                r1 = r0.z >= 0.0 ? tints[2] : (r0.y >= 0.0 ? tints[1] : r1);
                oC0 = r0.w >= 0.0 ? tints[3] : r1;
            }
        }
    }
    return oC0;
}
