// ps_3_0 shader decompiled by ps30
float adaptRate : register(c5);
float elapsedTime : register(c4);
float4 sampleOffsets[4] : register(c0);
sampler2D curLum : register(s0);
sampler2D prevLum : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = tex2D(curLum, (sampleOffsets[0].xy + texcoord0.xy));
    r0.x = r0.x + tex2D(curLum, (sampleOffsets[1].xy + texcoord0.xy)).x;
    r0.x = r0.x + tex2D(curLum, (sampleOffsets[2].xy + texcoord0.xy)).x;
    r1 = tex2D(curLum, (sampleOffsets[3].xy + texcoord0.xy));
    r0.x = (r0.x + r1.x) * 0.36067376;
    r1 = tex2D(prevLum, float2(0.5, 0.5));
    r0.x = exp2(r0.x) - r1.x;
    r0.y = (-elapsedTime * adaptRate) * 1.442695;
    r0.y = 1.0 - exp2(r0.y);
    oC0.xyz = r0.x * r0.y + r1.x;
    oC0.w = 1.0;
    return oC0;
}
