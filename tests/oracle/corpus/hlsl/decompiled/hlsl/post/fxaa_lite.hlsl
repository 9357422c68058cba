// ps_3_0 shader decompiled by ps30
float2 rcpFrame : register(c0);
sampler2D tex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0.x = dot(tex2D(tex, (texcoord0.xy - rcpFrame)).xyz, float3(0.299, 0.587, 0.114));
    r1 = rcpFrame.xyxy * float4(1.0, -1.0, -1.0, 1.0) + texcoord0.xyxy;
    r2 = tex2D(tex, r1.xy);
    r0.y = dot(tex2D(tex, r1.zw).xyz, float3(0.299, 0.587, 0.114));
    r0.z = dot(r2.xyz, float3(0.299, 0.587, 0.114));
    r0.w = r0.z + r0.x;
    r1.x = dot(tex2D(tex, (rcpFrame + texcoord0.xy)).xyz, float3(0.299, 0.587, 0.114));
    r1.yw = r0.yz + r1.x;
    r1.y = r0.w - r1.y;
    r0.w = r1.x + (r0.y + r0.w);
    r1.z = max((r0.w * 0.03125), 0.0078125);
    r2.x = -r1.y;
    r0.w = r2.x >= 0.0 ? r2.x : r1.y;
    r1.y = r0.y + r0.x;
    r2.y = r1.y - r1.w;
    r1.y = min(abs(r2.y), r0.w);
    r0.w = r1.z + r1.y;
    r2.xy = max(((1.0 / r0.w) * r2.xy), -8.0);
    r1.yz = min(r2.xy, 8.0) * rcpFrame;
    r4 = r1.yzyz * float4(-0.16666667, -0.16666667, 0.16666667, 0.16666667) + texcoord0.xyxy;
    r1.yzw = tex2D(tex, (r1.yz * -0.5 + texcoord0.xy)).xyz + tex2D(tex, (r1.yz * 0.5 + texcoord0.xy)).xyz;
    r2.xyz = tex2D(tex, r4.xy).xyz + tex2D(tex, r4.zw).xyz;
    r1.yzw = r2.xyz * 0.25 + (r1.yzw * 0.25);
    r2.xyz = r2.xyz * 0.5;
    r0.w = dot(r1.yzw, float3(0.299, 0.587, 0.114));
    r2.w = min(r0.z, r0.x);
    r3.x = max(r0.x, r0.z);
    r3.y = min(r1.x, r0.y);
    r3.z = max(r0.y, r1.x);
    r0.x = max(r3.x, r3.z);
    r0.y = min(r3.y, r2.w);
    r0.z = dot(tex2D(tex, texcoord0.xy).xyz, float3(0.299, 0.587, 0.114));
    r1.x = min(r0.y, r0.z);
    r0.x = max(r0.z, r0.x) - r0.w;
    r0.y = r0.w - r1.x;
    r0.xy = r0.xy >= 0.0 ? 0.0 : 1.0;
    oC0.xyz = -(r0.x + r0.y) >= 0.0 ? r1.yzw : r2.xyz;
    oC0.w = 1.0;
    return oC0;
}
