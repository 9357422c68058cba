// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
float4 a : register(c0);
float4 b : register(c1);
float4 c : register(c2);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = a;
    r1.x = r0.x * b.x;
    r2.xw = b.xw;
    r1.y = r0.x * r2.x + c.x;
    r1.z = dot(r0.xyz, b.xyz);
    r1.w = r0.w * r2.w + c.w;
    oC0 = r1;
    return oC0;
}
