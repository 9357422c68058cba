// ps_3_0 shader decompiled by ps30
float3 groundCol : register(c2);
float3 skyCol : register(c1);
float3 upVS : register(c0);
sampler2D normals : register(s0);
sampler2D albedo : register(s1);
sampler2D ao : register(s2);

void main(float4 texcoord0 : TEXCOORD0, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1)
{
    precise float4 r0 = 0, r1 = 0;
    oC0 = 0;
    oC1 = 0;
    r0.xyz = tex2D(normals, texcoord0.xy).xyz * 2.0 - 1.0;
    r0.x = dot(r0.xyz, upVS) * 0.5 + 0.5;
    r0.yzw = skyCol - groundCol;
    r0.xyz = (r0.x * r0.yzw + groundCol) * tex2D(albedo, texcoord0.xy).xyz;
    r1 = tex2D(ao, texcoord0.xy);
    oC0.xyz = r0.xyz * r1.x;
    oC1 = r1.x;
    oC0.w = 1.0;
}
