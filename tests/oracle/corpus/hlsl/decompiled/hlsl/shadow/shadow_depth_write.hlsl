// ps_3_0 shader decompiled by ps30
float alphaRef : register(c0);
float invFar : register(c1);
sampler2D alphaTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0 = tex2D(alphaTex, texcoord0.xy).w - alphaRef;
    clip(r0);
    r0.x = invFar * texcoord1.x;
    r0.y = ddy(r0.x);
    r0.y = r0.y * r0.y;
    r0.z = ddx(r0.x);
    r0.y = (r0.z * r0.z + r0.y) * 0.25;
    oC0.y = r0.x * r0.x + r0.y;
    oC0.x = r0.x;
    oC0.zw = float2(0.0, 1.0);
    return oC0;
}
