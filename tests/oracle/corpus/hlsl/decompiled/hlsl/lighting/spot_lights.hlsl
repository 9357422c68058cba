// ps_3_0 shader decompiled by ps30
float4 g_Spots[8] : register(c0); // the table's type: struct { float3 position; float3 direction; float3 color; float2 cosCone; }[2]
sampler2D g_Albedo : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.x = 1.0 / (g_Spots[7].y - g_Spots[7].x);
    r1.xyz = normalize((g_Spots[4].xyz - texcoord1.xyz));
    r0.y = dot(-r1.xyz, g_Spots[5].xyz) - g_Spots[7].x;
    r0.x = saturate(r0.x * r0.y);
    r0.y = r0.x * -2.0 + 3.0;
    r0.x = r0.x * r0.x;
    r0.xyz = (r0.x * r0.y) * g_Spots[6].xyz;
    r2.xyz = normalize(texcoord2.xyz);
    r0.w = saturate(dot(r2.xyz, r1.xyz));
    r0.xyz = r0.w * r0.xyz;
    r3.xyz = normalize((g_Spots[0].xyz - texcoord1.xyz));
    r1.x = dot(-r3.xyz, g_Spots[1].xyz);
    r1.y = saturate(dot(r2.xyz, r3.xyz));
    r0.w = saturate((1.0 / (g_Spots[3].y - g_Spots[3].x)) * (r1.x - g_Spots[3].x));
    r1.x = r0.w * -2.0 + 3.0;
    r0.w = r0.w * r0.w;
    r1.xzw = (r0.w * r1.x) * g_Spots[2].xyz;
    r0.xyz = r1.xzw * r1.y + r0.xyz;
    oC0.xyz = r0.xyz * tex2D(g_Albedo, texcoord0.xy).xyz;
    oC0.w = 1.0;
    return oC0;
}
