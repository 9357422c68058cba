// ps_3_0 shader decompiled by ps30
float4 damageColor : register(c4);
float damageFill : register(c1);
float4 emptyColor : register(c3);
float fill : register(c0);
float4 fullColor : register(c2);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = emptyColor;
    r0 = fill * (fullColor - r0) + r0;
    r1.x = fill - texcoord0.x;
    r0 = r1.x >= 0.0 ? r0 : emptyColor;
    r1.x = r1.x >= 0.0 ? -0.0 : -1.0;
    r1.y = damageFill - texcoord0.x;
    oC0 = (r1.y >= 0.0 ? r1.x : 0.0) >= 0.0 ? r0 : damageColor;
    return oC0;
}
