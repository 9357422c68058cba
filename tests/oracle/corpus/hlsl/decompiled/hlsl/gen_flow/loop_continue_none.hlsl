// ps_3_0 shader decompiled by ps30
float4 w[6] : register(c0);

float4 main(float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.x = w[1].w - texcoord1.w;
    r1 = (w[0].w - texcoord1.w) >= 0.0 ? w[0] : 0.0;
    r0 = r0.x >= 0.0 ? (r1 + w[1]) : r1;
    r0 = (w[2].w - texcoord1.w) >= 0.0 ? (r0 + w[2]) : r0;
    r0 = (w[3].w - texcoord1.w) >= 0.0 ? (r0 + w[3]) : r0;
    r0 = (w[4].w - texcoord1.w) >= 0.0 ? (r0 + w[4]) : r0;
    oC0 = (w[5].w - texcoord1.w) >= 0.0 ? (r0 + w[5]) : r0;
    return oC0;
}
