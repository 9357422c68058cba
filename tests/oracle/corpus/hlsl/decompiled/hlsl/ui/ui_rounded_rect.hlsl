// ps_3_0 shader decompiled by ps30
float4 borderColor : register(c2);
float4 fillColor : register(c1);
float4 rectSize : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xy = (abs(texcoord0.xy) - rectSize.xy) + rectSize.z;
    r1.xy = max(r0.xy, 0.0);
    r0.x = min(max(r0.x, r0.y), 0.0);
    r0.y = 1.0 / rsqrt(abs((dot(r1.xy, r1.xy) + 0.0)));
    r0.x = (r0.x + r0.y) - rectSize.z;
    r0.y = ddx(r0.x);
    r0.z = ddy(r0.x);
    r0.y = 1.0 / (abs(r0.z) + abs(r0.y));
    r0.z = saturate(r0.x * r0.y + 0.5);
    r0.x = r0.x + rectSize.w;
    r0.x = saturate(r0.x * r0.y + 0.5);
    r1 = r0.x * (borderColor - fillColor) + fillColor;
    oC0.w = (1.0 - r0.z) * r1.w;
    oC0.xyz = r1.xyz;
    return oC0;
}
