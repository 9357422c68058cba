// ps_3_0 shader decompiled by ps30
float4 outlineCol : register(c1);
float2 texelSz : register(c0);
float thickness : register(c2);
sampler2D selMask : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0.xy = float2(0.0, 1.0);
    r0.zw = r0.yx * thickness;
    r1.xy = r0.zw + float2(0.0, 1.0);
    r0.xy = r0.xy * thickness;
    r1.xy = (r1.xy * texelSz) * r0.xy + texcoord0.xy;
    r0.xy = (r0.xy + float2(1.0, 0.0)) * texelSz;
    r0.xy = r0.xy * r0.zw + texcoord0.xy;
    r1.z = max(tex2D(selMask, r0.xy).x, 0.0);
    r0 = tex2D(selMask, r1.xy);
    r2 = thickness * texelSz.xyxy;
    r3 = r2.zwzw * float4(-1.0, 0.0, 0.0, -1.0) + texcoord0.xyxy;
    r4 = tex2D(selMask, r3.xy);
    r0.y = max(r1.z, r4.x);
    r0.x = max(max(r0.y, r0.x), tex2D(selMask, r3.zw).x);
    r1 = r2.zwzw * float4(0.707, 0.707, -0.707, 0.707) + texcoord0.xyxy;
    r2 = r2 * float4(0.707, -0.707, -0.707, -0.707) + texcoord0.xyxy;
    r3 = tex2D(selMask, r1.xy);
    r1 = tex2D(selMask, r1.zw);
    r1.y = max(r0.x, r3.x);
    r0.x = max(r1.y, r1.x);
    r1 = tex2D(selMask, r2.xy);
    r2 = tex2D(selMask, r2.zw);
    r2.y = max(r0.x, r1.x);
    oC0 = saturate(max(r2.y, r2.x) - (tex2D(selMask, texcoord0.xy).x)) * outlineCol;
    return oC0;
}
