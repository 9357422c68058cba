// ps_3_0 shader decompiled by ps30
float4 detailFade : register(c0);
float detailTile : register(c1);
sampler2D macroColor : register(s0);
sampler2D detailA : register(s1);
sampler2D detailB : register(s2);
sampler2D blendMask : register(s3);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    r0 = tex2D(macroColor, texcoord0.xy);
    r1.x = 1.0 - saturate((texcoord1.x - detailFade.x) * detailFade.y);
    r1.yz = detailTile * texcoord0.xy;
    r2.xy = ddx(r1.yz);
    r2.zw = ddy(r1.yz);
    if (-r1.x < 0.0) {
        r3 = tex2D(blendMask, texcoord0.xy);
        r4 = tex2Dgrad(detailA, r1.yz, r2.xy, r2.zw);
        r2 = tex2Dgrad(detailB, r1.yz, r2.xy, r2.zw);
        r5 = lerp(r4, r2, r3.x);
    } else {
        r5 = 0.5;
    }
    oC0 = r0 * (r1.x * (r5 * 2.0 - 1.0) + 1.0);
    return oC0;
}
