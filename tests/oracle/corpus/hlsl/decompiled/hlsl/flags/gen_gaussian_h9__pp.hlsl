// ps_3_0 shader decompiled by ps30
float texelWidth : register(c0);
sampler2D inputTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r1.x = texelWidth;
    r2 = r1.x * float4(1.0, 0.0, 2.0, 0.0) + texcoord0.xyxy;
    r3 = tex2D(inputTex, r2.xy);
    r0 = tex2D(inputTex, texcoord0.xy) * 0.22702703 + (r3 * 0.19459459);
    r3 = r1.x * float4(-1.0, -0.0, -2.0, -0.0) + texcoord0.xyxy;
    r4 = tex2D(inputTex, r3.xy);
    r0 = r4 * 0.19459459 + r0;
    r0 = tex2D(inputTex, r3.zw) * 0.12162162 + (tex2D(inputTex, r2.zw) * 0.12162162 + r0);
    r2 = r1.x * float4(3.0, 0.0, 4.0, 0.0) + texcoord0.xyxy;
    r3 = tex2D(inputTex, r2.xy);
    r0 = r3 * 0.054054055 + r0;
    r1 = r1.x * float4(-3.0, -0.0, -4.0, -0.0) + texcoord0.xyxy;
    r3 = tex2D(inputTex, r1.xy);
    r0 = r3 * 0.054054055 + r0;
    oC0 = tex2D(inputTex, r1.zw) * 0.016216217 + (tex2D(inputTex, r2.zw) * 0.016216217 + r0);
    return oC0;
}
