// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
float4 k : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 color0 : COLOR0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0;
    r0.x = (0.5 - texcoord0.x) >= 0.0 ? k.y : k.x;
    r0.y = texcoord0.y * k.w + (texcoord0.x * k.z);
    r0.w = lerp(k.x, k.y, texcoord0.x);
    r0.z = color0.x * 4.0;
    oC0 = r0;
    return oC0;
}
