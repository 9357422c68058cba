// ps_3_0 shader decompiled by ps30
float4x4 invProj : register(c0);
float3 lightColor : register(c5);
float3 lightDirVS : register(c4);
sampler2D gAlbedo : register(s0);
sampler2D gNormal : register(s1);
sampler2D gDepth : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.z = tex2D(gDepth, texcoord0.xy).x;
    r0.xyw = texcoord0.xyx * float3(2.0, -2.0, 0.0) + float3(-1.0, 1.0, 1.0);
    r2.x = dot(r0, invProj._m00_m10_m20_m30);
    r2.y = dot(r0, invProj._m01_m11_m21_m31);
    r2.z = dot(r0, invProj._m02_m12_m22_m32);
    r0.xyz = (1.0 / dot(r0, invProj._m03_m13_m23_m33)) * r2.xyz;
    r0.w = rsqrt(abs(dot(-r0.xyz, -r0.xyz)));
    r1.xyz = normalize((-r0.xyz * r0.w + lightDirVS));
    r0.xyz = tex2D(gNormal, texcoord0.xy).xyz * 2.0 - 1.0;
    r0.w = saturate(dot(r0.xyz, r1.xyz));
    r0.x = saturate(dot(r0.xyz, lightDirVS));
    r1 = tex2D(gAlbedo, texcoord0.xy);
    r0.y = r1.w * 255.0;
    r0.y = r0.x * pow(abs(r0.w), r0.y);
    oC0.xyz = (r1.xyz * r0.x + r0.y) * lightColor;
    oC0.w = 1.0;
    return oC0;
}
