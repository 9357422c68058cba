// ps_3_0 shader decompiled by ps30
float4 outlineColor : register(c1);
float outlineWidth : register(c2);
float4 shadowColor : register(c4);
float2 shadowOffset : register(c3);
float4 textColor : register(c0);
sampler2D fontAtlas : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.x = 0.5 - outlineWidth;
    r1 = tex2D(fontAtlas, texcoord0.xy);
    r0.y = ddx(r1.w);
    r0.z = ddy(r1.w);
    r0.y = abs(r0.z) + abs(r0.y);
    r0.z = r0.y * 0.7 + r0.x;
    r0.x = r0.y * -0.7 + r0.x;
    r0.z = r0.z - r0.x;
    r0.x = r1.w - r0.x;
    r0.z = 1.0 / r0.z;
    r0.x = saturate(r0.z * r0.x);
    r0.z = r0.x * -2.0 + 3.0;
    r0.x = r0.x * r0.x;
    r0.x = r0.x * r0.z;
    r0.zw = r0.y * float2(-0.7, -2.8) + 0.5;
    r1.xy = (r0.y * float2(0.7, 2.8) + 0.5) - r0.zw;
    r0.y = r1.w - r0.z;
    r0.z = 1.0 / r1.x;
    r0.y = saturate(r0.z * r0.y);
    r0.z = r0.y * -2.0 + 3.0;
    r0.y = r0.y * r0.y;
    r2 = (r0.y * r0.z) * (textColor - outlineColor) + outlineColor;
    r2.w = r0.x * r2.w;
    r3 = tex2D(fontAtlas, (texcoord0.xy - shadowOffset));
    r0.x = saturate((1.0 / r1.y) * (r3.w - r0.w));
    r0.y = r0.x * -2.0 + 3.0;
    r0.x = r0.x * r0.x;
    r0.w = (r0.x * r0.y) * shadowColor.w;
    r0.xyz = shadowColor.xyz;
    oC0 = r2.w * (r2 - r0) + r0;
    return oC0;
}
