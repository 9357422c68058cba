// ps_3_0 shader decompiled by ps30
float2x2 M : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = 0.0;
    r1.x = dot(texcoord0.xy, M._m00_m10) + r0.x;
    r1.y = dot(texcoord0.xy, M._m01_m11) + r0.x;
    oC0 = r1.xyxy;
    return oC0;
}
