// ps_3_0 shader decompiled by ps30
float2x2 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.xy = M._m00_m10;
    r0.y = r0.y * M._m01;
    oC0 = (r0.x * M._m11 - r0.y) * texcoord0.x;
    return oC0;
}
