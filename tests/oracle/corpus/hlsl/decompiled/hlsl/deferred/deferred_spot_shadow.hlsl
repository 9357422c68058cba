// ps_3_0 shader decompiled by ps30
float shadowBias : register(c8);
float3 spotColor : register(c6);
float2 spotCos : register(c7);
float3 spotDir : register(c5);
float3 spotPos : register(c4);
float4x4 viewToLight : register(c0);
sampler2D gb_normal : register(s0);
sampler2D gb_depth : register(s1);
sampler2D shadowMap : register(s2);
sampler2D cookie : register(s3);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0.xy = (1.0 / texcoord0.w) * texcoord0.xy;
    r1 = tex2D(gb_depth, r0.xy);
    r0.xyz = tex2D(gb_normal, r0.xy).xyz * 2.0 - 1.0;
    r2.xyz = r1.x * texcoord1.xyz;
    r3.xyz = normalize((texcoord1.xyz * -r1.x + spotPos));
    r2.w = 1.0;
    r0.w = 1.0 / dot(r2, viewToLight._m03_m13_m23_m33);
    r1.x = dot(r2, viewToLight._m00_m10_m20_m30);
    r1.y = dot(r2, viewToLight._m01_m11_m21_m31);
    r1.z = dot(r2, viewToLight._m02_m12_m22_m32) * r0.w - shadowBias;
    r1.xy = (r0.w * r1.xy) * float2(0.5, -0.5) + 0.5;
    r2 = tex2D(shadowMap, r1.xy);
    r1.xyw = tex2D(cookie, r1.xy).xyz * spotColor;
    r0.w = (r1.z - r2.x) >= 0.0 ? 0.0 : 1.0;
    r0.x = saturate(dot(r0.xyz, r3.xyz));
    r0.y = dot(-r3.xyz, spotDir) - spotCos.x;
    r0.z = 1.0 / (spotCos.y - spotCos.x);
    r0.yzw = r0.w * (saturate(r0.z * r0.y) * r1.xyw);
    oC0.xyz = r0.x * r0.yzw;
    oC0.w = 1.0;
    return oC0;
}
