// ps_3_0 shader decompiled by ps30
float4 filterMode : register(c0); // the table's type: int
float levels : register(c2);
float2 resolution : register(c1);
sampler2D src : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xy = (resolution * texcoord0.xy) * 0.125;
    r0.zw = frac(r0.xy);
    r0.xy = (r0.xy - r0.zw) + 0.5;
    r1.x = 1.0 / resolution.x;
    r1.y = 1.0 / resolution.y;
    r0.xy = (r0.xy * 8.0) * r1.xy;
    r0.zw = float2(-1.0, -2.0) + filterMode.x;
    r1 = tex2D(src, (-abs(r0.z) >= 0.0 ? r0.xy : texcoord0.xy));
    r0.xyz = r1.xyz * levels;
    r2.xyz = frac(r0.xyz);
    r0.xyz = (r0.xyz - r2.xyz) * (1.0 / levels);
    r0.xyz = -abs(r0.w) >= 0.0 ? r0.xyz : r1.xyz;
    r2.x = dot(r1.xyz, float3(0.393, 0.769, 0.189));
    r2.y = dot(r1.xyz, float3(0.349, 0.686, 0.168));
    r2.z = dot(r1.xyz, float3(0.272, 0.534, 0.131));
    r0.w = abs(filterMode.x);
    oC0.xyz = -r0.w >= 0.0 ? r2.xyz : r0.xyz;
    oC0.w = 1.0;
    return oC0;
}
