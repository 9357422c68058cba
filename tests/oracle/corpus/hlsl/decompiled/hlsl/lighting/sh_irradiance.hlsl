// ps_3_0 shader decompiled by ps30
float4 cAb : register(c2);
float4 cAg : register(c1);
float4 cAr : register(c0);
float4 cBb : register(c5);
float4 cBg : register(c4);
float4 cBr : register(c3);
float4 cC : register(c6);

float4 main(float4 texcoord0 : TEXCOORD0, float4 color0 : COLOR0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.w = 1.0;
    r0.xyz = normalize(texcoord0.xyz);
    r1.x = dot(cAr, r0);
    r1.y = dot(cAg, r0);
    r1.z = dot(cAb, r0);
    r2 = r0.yzzx * r0.xyzz;
    r3.x = dot(cBr, r2);
    r3.y = dot(cBg, r2);
    r3.z = dot(cBb, r2);
    r0.y = r0.y * r0.y;
    r0.x = r0.x * r0.x - r0.y;
    oC0.xyz = (cC.xyz * r0.x + (r1.xyz + r3.xyz)) * color0.xyz;
    oC0.w = color0.w;
    return oC0;
}
