// ps_3_0 shader decompiled by ps30
float4 c[3] : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.x = dot(texcoord0, c[0]);
    r0.y = dot(texcoord0, c[1]);
    r0.z = dot(texcoord0, c[2]);
    r0.w = 1.0;
    oC0 = r0;
    return oC0;
}
