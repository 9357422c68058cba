// ps_3_0 shader decompiled by ps30
float exposureScale : register(c1);
float rgbmRange : register(c0);
sampler2D rgbmTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(rgbmTex, texcoord0.xy);
    r0.xyz = r0.w * r0.xyz;
    r0.xyz = (r0.xyz * rgbmRange) * exposureScale;
    r0.w = 1.0 / rgbmRange;
    r0.xyz = r0.w * r0.xyz;
    r1.x = max(r0.x, r0.y);
    r1.y = max(r0.z, 1.0e-6);
    r0.w = saturate(max(r1.x, r1.y)) * 255.0;
    r1.x = frac(-r0.w);
    r0.w = (r0.w + r1.x) * 0.003921569;
    oC0.w = r0.w;
    oC0.xyz = r0.xyz * (1.0 / r0.w);
    return oC0;
}
