// ps_3_0 shader decompiled by ps30
float4 borders : register(c0);
float4 scaleInfo : register(c1);
sampler2D panelTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.xy = scaleInfo.xy;
    r1.xy = 1.0 - borders.yw;
    r0.zw = (r0.xy - borders.xz) - r1.xy;
    r0.z = 1.0 / r0.z;
    r0.w = 1.0 / r0.w;
    r1.zw = texcoord0.xy * r0.xy - borders.xz;
    r2.x = lerp(borders.x, borders.y, (r0.z * r1.z));
    r2.yz = 1.0 - texcoord0.xy;
    r0.xy = r2.yz * -r0.xy + 1.0;
    r1.xy = r2.yz * scaleInfo.xy - r1.xy;
    r0.x = r1.x >= 0.0 ? r2.x : r0.x;
    r2.xy = scaleInfo.xy * texcoord0.xy;
    r3.x = r1.z >= 0.0 ? r0.x : r2.x;
    r1.x = lerp(borders.z, borders.w, (r0.w * r1.w));
    r3.y = r1.w >= 0.0 ? (r1.y >= 0.0 ? r1.x : r0.y) : r2.y;
    oC0 = tex2D(panelTex, r3.xy);
    return oC0;
}
