// ps_3_0 shader decompiled by ps30
float blend : register(c1);
float4 texel : register(c0);
sampler2D lowMip : register(s0);
sampler2D highMip : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r1 = (texel.xy * texel.z).xyxy * float4(0.0, -1.0, -1.0, 0.0) + texcoord0.xyxy;
    r2 = tex2D(lowMip, r1.xy);
    r0.xyz = r2.xyz * 2.0 + tex2D(lowMip, (texel.z * -texel.xy + texcoord0.xy)).xyz;
    r2 = float2(0.0, 1.0).xyyx * texel.z;
    r4 = (r2 + float4(1.0, 0.0, 0.0, 1.0)) * texel.xyxy;
    r3.xy = r4.xy * (r2.zw + float2(0.0, -1.0)) + texcoord0.xy;
    r0.xyz = tex2D(lowMip, r1.zw).xyz * 2.0 + (r0.xyz + tex2D(lowMip, r3.xy).xyz);
    r0.xyz = tex2D(lowMip, texcoord0.xy).xyz * 4.0 + r0.xyz;
    r1 = r4 * r2.zwxy + texcoord0.xyxy;
    r2.xy = r4.zw * (r2.xy + float2(-1.0, 0.0)) + texcoord0.xy;
    r3 = tex2D(lowMip, r1.xy);
    r0.xyz = r3.xyz * 2.0 + r0.xyz;
    r0.xyz = tex2D(lowMip, r1.zw).xyz * 2.0 + (tex2D(lowMip, r2.xy).xyz + r0.xyz);
    r0.xyz = r0.xyz + tex2D(lowMip, (texel.z * texel.xy + texcoord0.xy)).xyz;
    oC0.xyz = (r0.xyz * blend) * 0.0625 + tex2D(highMip, texcoord0.xy).xyz;
    oC0.w = 1.0;
    return oC0;
}
