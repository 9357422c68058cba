// ps_3_0 shader decompiled by ps30
float4 c0 : register(c0);
float4 c1 : register(c1);
float4 c2 : register(c2);
sampler2D s0 : register(s0);
sampler2D s1 : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0 = tex2D(s1, c2.xy);
    r0.y = (1.0 / r0.x) * c0.x;
    r1 = tex2D(s0, texcoord0.xy);
    r2.x = dot(r1.xyz, c1.xyz);
    r2.y = r2.x * r0.y;
    r2.z = r2.x * (r0.x * c0.y) + c0.w;
    r2.w = 1.0 / (r2.y + c0.w);
    r2.z = (r2.z * r2.w) * r0.y;
    r3.xyz = r1.xyz * (-r2.x >= 0.0 ? c0.z : r2.z);
    r3.w = r1.w;
    oC0 = saturate(r3);
    return oC0;
}
