// ps_3_0 shader decompiled by ps30
float3 LightCol : register(c3);
float LightInvRadius : register(c2);
float3 LightPosVS : register(c1);
float4 ScreenSize : register(c0);
sampler2D NormalBuf : register(s0);
sampler2D DepthBuf : register(s1);
sampler2D ColorBuf : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0, float2 vpos : VPOS) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.x = 1.0 / texcoord0.z;
    r0.yz = (0.5 + vpos) * ScreenSize.xy;
    r1 = tex2D(DepthBuf, r0.yz);
    r1.xyz = texcoord0.xyz * -(r0.x * r1.x) + LightPosVS;
    r0.x = rsqrt(abs(dot(r1.xyz, r1.xyz)));
    r1.xyz = r0.x * r1.xyz;
    r0.x = 1.0 / r0.x;
    r0.w = 1.0;
    r0.x = saturate(r0.x * -LightInvRadius + r0.w);
    r0.x = r0.x * r0.x;
    r2 = tex2D(NormalBuf, r0.yz);
    r0.yzw = tex2D(ColorBuf, r0.yz).xyz * LightCol;
    r0.yzw = r0.yzw * saturate(dot(normalize((r2.xyz * 2.0 - 1.0)), r1.xyz));
    oC0.xyz = r0.yzw * r0.x;
    oC0.w = 0.0;
    return oC0;
}
