// ps_3_0 shader decompiled by ps30
float3 lightVS : register(c5);
float4x4 proj : register(c0);
float4 sphereVS : register(c4);

void main(float4 texcoord0 : TEXCOORD0, out precise float4 oC0 : COLOR0, out precise float oDepth : DEPTH)
{
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    oC0 = 0;
    oDepth = 0;
    r0.x = sphereVS.w * -sphereVS.w + dot(sphereVS.xyz, sphereVS.xyz);
    r1.xyz = normalize(texcoord0.xyz);
    r0.y = dot(r1.xyz, sphereVS.xyz);
    r2 = r0.y * r0.y - r0.x;
    r0.x = 1.0 / rsqrt(abs(r2.w));
    r0.x = r0.y - r0.x;
    clip(r2);
    r2.xyz = r0.x * r1.xyz;
    r0.xyz = r1.xyz * r0.x - sphereVS.xyz;
    r2.w = 1.0;
    oDepth = (1.0 / dot(r2, proj._m03_m13_m23_m33)) * dot(r2, proj._m02_m12_m22_m32);
    r0.w = 1.0 / sphereVS.w;
    oC0.xyz = saturate(dot((r0.w * r0.xyz), lightVS));
    oC0.w = 1.0;
}
