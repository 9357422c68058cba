// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.x = log2(abs(texcoord0.x));
    r0.y = log2(abs(texcoord0.y));
    r0.z = log2(abs(texcoord0.z));
    r0.w = log2(abs(texcoord0.w));
    r0 = r0 * texcoord1;
    oC0.x = exp2(r0.x);
    oC0.y = exp2(r0.y);
    oC0.z = exp2(r0.z);
    oC0.w = exp2(r0.w);
    return oC0;
}
