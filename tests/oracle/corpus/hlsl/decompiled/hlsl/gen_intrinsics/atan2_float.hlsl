// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = texcoord1.x;
    r0.y = 1.0 / max(abs(texcoord0.x), abs(r0.x));
    r0.y = r0.y * min(abs(r0.x), abs(texcoord0.x));
    r0.z = r0.y * r0.y;
    r0.w = r0.z * 0.0208351 - 0.085133;
    r0.w = r0.z * r0.w + 0.180141;
    r0.w = r0.z * r0.w - 0.3302995;
    r0.z = r0.z * r0.w + 0.999866;
    r0.y = r0.z * r0.y;
    r0.z = r0.y * -2.0 + 1.5707964;
    r0.w = (abs(r0.x) - abs(texcoord0.x)) >= 0.0 ? 0.0 : 1.0;
    r0.y = r0.z * r0.w + r0.y;
    r0.z = texcoord1.x >= 0.0 ? -0.0 : -3.1415927;
    r0.y = r0.z + r0.y;
    r0.z = r0.y + r0.y;
    r0.w = max(texcoord0.x, r0.x) >= 0.0 ? 1.0 : 0.0;
    r0.x = min(r0.x, texcoord0.x) >= 0.0 ? 0.0 : r0.w;
    oC0 = r0.x * -r0.z + r0.y;
    return oC0;
}
