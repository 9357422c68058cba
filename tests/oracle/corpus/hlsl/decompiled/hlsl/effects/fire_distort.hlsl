// ps_3_0 shader decompiled by ps30
float2 distortion : register(c2);
float3 scrollSpeeds : register(c1);
float timeSec : register(c0);
sampler2D flameShape : register(s0);
sampler2D noiseA : register(s1);
sampler2D noiseB : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.yw = timeSec * scrollSpeeds.xy;
    r0.xz = 0.0;
    r0 = texcoord0.xyxy * float4(1.0, 2.0, 1.0, 3.0) - r0;
    r1 = tex2D(noiseA, r0.xy);
    r0.xy = tex2D(noiseB, r0.zw).xy + r1.xy;
    r0.xy = (r0.xy - 1.0) * distortion;
    r0.z = 1.0 - texcoord0.y;
    r0 = tex2D(flameShape, saturate(r0.xy * r0.z + texcoord0.xy));
    r1.y = r0.w * 0.4 + 0.6;
    r1.xzw = float3(1.0, 0.2, 1.0);
    oC0 = r0 * r1;
    return oC0;
}
