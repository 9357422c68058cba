// ps_3_0 shader decompiled by ps30
float4 scale : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = rsqrt(abs(dot(texcoord0.xyz, texcoord0.xyz)));
    r0.x = dot((r0.x * texcoord0.xyz), texcoord1.xyz);
    r0.y = r0.x - 0.0;
    r0.x = r0.y >= 0.0 ? r0.x : 0.0;
    r0.y = r0.x - 1.0;
    r0.x = r0.y >= 0.0 ? 1.0 : r0.x;
    r0.xyz = (r0.x * scale.yxz);
    r0.x = r0.x;
    r0.w = r0.x * r0.x;
    r1.x = -(r0.w * 2.0);
    r0.w = (r0.w * (r1.x + 3.0));
    oC0.xyz = r0.w * r0.yxz;
    oC0.w = r0.w;
    return oC0;
}
