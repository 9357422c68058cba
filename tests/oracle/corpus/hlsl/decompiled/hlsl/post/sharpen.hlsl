// ps_3_0 shader decompiled by ps30
float amount : register(c1);
float limit : register(c2);
float2 px : register(c0);
sampler2D frameTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.xy = float2(1.0, 0.0);
    r1 = px.xxxy * r0.xyyx + texcoord0.xyxy;
    r2 = tex2D(frameTex, r1.xy);
    r1 = tex2D(frameTex, r1.zw);
    r0 = px.xxxy * -r0.xyyx + texcoord0.xyxy;
    r3 = tex2D(frameTex, r0.xy);
    r0.xyz = tex2D(frameTex, r0.zw).xyz + (r1.xyz + (r2.xyz + r3.xyz));
    r1 = tex2D(frameTex, texcoord0.xy);
    r0.xyz = r0.xyz * -0.25 + r1.xyz;
    r2.xyz = max((r0.xyz * amount), -limit);
    oC0.xyz = min(limit, r2.xyz) + r1.xyz;
    oC0.w = 1.0;
    return oC0;
}
