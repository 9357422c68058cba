// ps_3_0 shader decompiled by ps30
float2 TexelSize : register(c0);
sampler2D Src : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = TexelSize.xyxy * float2(1.0, -1.0).xyyx + texcoord0.xyxy;
    r1 = tex2D(Src, r0.xy);
    r0 = tex2D(Src, r0.zw);
    r0.w = 1.0 / (dot(r1.xyz, float3(0.299, 0.587, 0.114)) + 1.0);
    r1.xyz = r0.w * r1.xyz;
    r2 = tex2D(Src, (texcoord0.xy - TexelSize));
    r1.w = 1.0 / (dot(r2.xyz, float3(0.299, 0.587, 0.114)) + 1.0);
    r1.xyz = r2.xyz * r1.w + r1.xyz;
    r0.w = r0.w + r1.w;
    r1.w = 1.0 / (dot(r0.xyz, float3(0.299, 0.587, 0.114)) + 1.0);
    r0.xyz = r0.xyz * r1.w + r1.xyz;
    r0.w = r0.w + r1.w;
    r1 = tex2D(Src, (TexelSize + texcoord0.xy));
    r1.w = dot(r1.xyz, float3(0.299, 0.587, 0.114));
    r1.w = 1.0 / (r1.w + 1.0);
    r0.xyz = r1.xyz * r1.w + r0.xyz;
    r0.w = r0.w + r1.w;
    r1 = tex2D(Src, texcoord0.xy);
    r1.w = dot(r1.xyz, float3(0.299, 0.587, 0.114));
    r1.w = 1.0 / (r1.w + 1.0);
    r0.w = 1.0 / (r1.w * 4.0 + r0.w);
    r0.xyz = (r1.w * r1.xyz) * 4.0 + r0.xyz;
    oC0.xyz = r0.w * r0.xyz;
    oC0.w = 1.0;
    return oC0;
}
