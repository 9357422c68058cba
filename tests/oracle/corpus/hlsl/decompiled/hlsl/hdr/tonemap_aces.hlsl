// ps_3_0 shader decompiled by ps30
float g_Exposure : register(c0);
sampler2D s_hdr : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = tex2D(s_hdr, texcoord0.xy);
    r0.w = exp2(g_Exposure);
    r0.xyz = r0.w * r0.xyz;
    r1.xyz = r0.xyz * (r0.xyz * 2.51 + 0.03);
    r0.xyz = r0.xyz * (r0.xyz * 2.43 + 0.59) + 0.14;
    r2.x = 1.0 / r0.x;
    r2.y = 1.0 / r0.y;
    r2.z = 1.0 / r0.z;
    oC0.xyz = saturate(r1.xyz * r2.xyz);
    oC0.w = 1.0;
    return oC0;
}
