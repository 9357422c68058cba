// ps_3_0 shader decompiled by ps30
float4 hi : register(c1);
float4 lo : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = texcoord1;
    r1 = max(r0, texcoord0);
    r0 = texcoord0 - r0;
    r0 = (-abs(r0) >= 0.0 ? 1.0 : 0.0) + (r1 + (texcoord0.x >= 0.0 ? hi : lo));
    r1.x = 1.0 / texcoord1.x;
    r1.y = 1.0 / texcoord1.y;
    r1.z = 1.0 / texcoord1.z;
    r1.w = 1.0 / texcoord1.w;
    oC0 = r0 + (-abs(texcoord1) >= 0.0 ? 0.0 : r1);
    return oC0;
}
