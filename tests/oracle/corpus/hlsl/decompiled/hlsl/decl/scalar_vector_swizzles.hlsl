// ps_3_0 shader decompiled by ps30
float4 a : register(c0);
float4 b : register(c1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.w = texcoord0.y * a.w + dot(texcoord0.zyx, a.xyz);
    r0.z = a.w * texcoord0.x;
    r0.xy = b.yx + texcoord0.z;
    r0 = r0 * 0.5 + r0.wwzz;
    oC0.yz = max(r0.yz, a.wx);
    oC0.xw = r0.xw;
    return oC0;
}
