// ps_3_0 shader decompiled by ps30
float3 lightTS : register(c1);
float2 scaleBias : register(c0);
sampler2D colorMap : register(s0);
sampler2D normalMap : register(s1);
sampler2D heightMap : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xy = rsqrt(abs(dot(texcoord1.xyz, texcoord1.xyz))) * texcoord1.xy;
    r0.z = tex2D(heightMap, texcoord0.xy).x * scaleBias.x + scaleBias.y;
    r0.xy = r0.z * r0.xy + texcoord0.xy;
    r1 = tex2D(normalMap, r0.xy);
    r2.xyz = normalize((r1.xyz * 2.0 - 1.0));
    oC0 = tex2D(colorMap, r0.xy) * saturate(dot(r2.xyz, normalize(lightTS)));
    return oC0;
}
