// ps_3_0 shader decompiled by ps30
float texelWidth : register(c0);
sampler2D inputTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = tex2D(inputTex, texcoord0.xy) * 0.22702703;
    r1.xy = float2(1.0, 0.0) * texelWidth;
    r2 = tex2D(inputTex, (r1.xy + texcoord0.xy));
    r1.xy = -r1.xy;
    r1 = tex2D(inputTex, (r1.xy + texcoord0.xy));
    r0 = (r0 + (r2 * 0.19459459)) + (r1 * 0.19459459);
    r1.xyw = float3(2.0, 0.0, 3.0);
    r1.xz = r1.xy * texelWidth;
    r2 = tex2D(inputTex, (r1.xz + texcoord0.xy));
    r0 = r0 + (r2 * 0.12162162);
    r1.xz = -r1.xz;
    r0 = r0 + (tex2D(inputTex, (r1.xz + texcoord0.xy)) * 0.12162162);
    r1.xy = r1.wy * texelWidth;
    r2 = tex2D(inputTex, (r1.xy + texcoord0.xy));
    r1.xy = -r1.xy;
    r1 = tex2D(inputTex, (r1.xy + texcoord0.xy));
    r0 = (r0 + (r2 * 0.054054055)) + (r1 * 0.054054055);
    r1.xy = float2(4.0, 0.0) * texelWidth;
    r0 = r0 + (tex2D(inputTex, (r1.xy + texcoord0.xy)) * 0.016216217);
    r1.xy = -r1.xy;
    r1 = tex2D(inputTex, (r1.xy + texcoord0.xy));
    oC0 = (r0 + (r1 * 0.016216217));
    return oC0;
}
