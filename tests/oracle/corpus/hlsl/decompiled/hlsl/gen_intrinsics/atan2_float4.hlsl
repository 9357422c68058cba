// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0 = texcoord1;
    r2 = max(abs(texcoord0), abs(r0));
    r3.x = 1.0 / r2.x;
    r3.y = 1.0 / r2.y;
    r3.z = 1.0 / r2.z;
    r3.w = 1.0 / r2.w;
    r1 = min(abs(r0), abs(texcoord0)) * r3;
    r2 = r1 * r1;
    r3 = r2 * (r2 * (r2 * 0.0208351 - 0.085133) + 0.180141) - 0.3302995;
    r1 = r1 * (r2 * r3 + 0.999866);
    r1 = (r1 * -2.0 + 1.5707964) * ((abs(r0) - abs(texcoord0)) >= 0.0 ? 0.0 : 1.0) + r1;
    r1 = r1 + (texcoord1 >= 0.0 ? -0.0 : -3.1415927);
    r3 = max(texcoord0, r0);
    r4 = min(r0, texcoord0);
    oC0 = (r4 >= 0.0 ? 0.0 : (r3 >= 0.0 ? 1.0 : 0.0)) * -(r1 + r1) + r1;
    return oC0;
}
