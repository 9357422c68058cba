// ps_3_0 shader decompiled by ps30
float3 L : register(c0);
float3 scatterTint : register(c2);
float wrap : register(c1);
sampler2D skinTex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = dot(normalize(texcoord1.xyz), L) + wrap;
    r1.xw = float2(1.0, 2.0);
    r0.y = 1.0 / (r1.x + wrap);
    r0.x = saturate(r0.y * r0.x);
    r0.y = wrap * -r1.w + r0.x;
    r0.z = 1.0 / -wrap;
    r0.y = saturate(r0.z * r0.y);
    r0.z = r0.y * -2.0 + 3.0;
    r0.y = r0.y * r0.y;
    r0.y = r0.y * r0.z;
    r0.z = 1.0 / wrap;
    r0.z = saturate(r0.z * r0.x);
    r0.w = r0.z * -2.0 + 3.0;
    r0.z = r0.z * r0.z;
    r0.z = r0.z * r0.w;
    r0.y = r0.y * r0.z;
    oC0.xyz = (r0.y * scatterTint + r0.x) * tex2D(skinTex, texcoord0.xy).xyz;
    oC0.w = 1.0;
    return oC0;
}
