// ps_3_0 shader decompiled by ps30
float4 sampleOffsets[9] : register(c0);
sampler2D lumTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(lumTex, (sampleOffsets[0].xy + texcoord0.xy));
    r0.x = r0.x + tex2D(lumTex, (sampleOffsets[1].xy + texcoord0.xy)).x;
    r0.x = r0.x + tex2D(lumTex, (sampleOffsets[2].xy + texcoord0.xy)).x;
    r0.x = r0.x + tex2D(lumTex, (sampleOffsets[3].xy + texcoord0.xy)).x;
    r0.x = r0.x + tex2D(lumTex, (sampleOffsets[4].xy + texcoord0.xy)).x;
    r0.x = r0.x + tex2D(lumTex, (sampleOffsets[5].xy + texcoord0.xy)).x;
    r0.x = r0.x + tex2D(lumTex, (sampleOffsets[6].xy + texcoord0.xy)).x;
    r0.x = r0.x + tex2D(lumTex, (sampleOffsets[7].xy + texcoord0.xy)).x;
    r1 = tex2D(lumTex, (sampleOffsets[8].xy + texcoord0.xy));
    oC0.x = (r0.x + r1.x) * 0.11111111;
    oC0.yzw = float3(0.0, 0.0, 1.0);
    return oC0;
}
