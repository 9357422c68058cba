// ps_3_0 shader decompiled by ps30
float4 a : register(c0);
float4 b : register(c1);
float4 c : register(c2);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = a;
    oC0.z = dot(r0.xyz, b.xyz);
    oC0.yw = r0.xw * b.xw + c.xw;
    oC0.x = (r0.x * b.x);
    return oC0;
}
