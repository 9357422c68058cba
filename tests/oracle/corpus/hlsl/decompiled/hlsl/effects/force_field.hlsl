// ps_3_0 shader decompiled by ps30
float3 eyeW : register(c5);
float4 hits[4] : register(c0);
float4 shieldColor : register(c4);
sampler2D hexTex : register(s0);
sampler2D depthMap : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, float4 texcoord3 : TEXCOORD3) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = texcoord1.xyz - hits[0].xyz;
    r0.x = dot(r0.xyz, r0.xyz);
    r0.x = 1.0 / rsqrt(abs(r0.x));
    r1.xw = float2(1.0, 3.0);
    r0.x = 1.0 - abs((hits[0].w * -r1.w + r0.x));
    r0.y = saturate(r1.x - hits[0].w);
    r0.y = r0.y * r0.x;
    r0.x = r0.x >= 0.0 ? r0.y : 0.0;
    r0.yzw = texcoord1.xyz - hits[1].xyz;
    r0.y = dot(r0.yzw, r0.yzw);
    r0.y = 1.0 / rsqrt(abs(r0.y));
    r0.y = 1.0 - abs((hits[1].w * -r1.w + r0.y));
    r0.z = saturate(r1.x - hits[1].w);
    r0.z = r0.z * r0.y;
    r0.y = r0.y >= 0.0 ? r0.z : 0.0;
    r0.x = r0.y + r0.x;
    r0.yzw = texcoord1.xyz - hits[2].xyz;
    r0.y = dot(r0.yzw, r0.yzw);
    r0.y = 1.0 / rsqrt(abs(r0.y));
    r0.y = 1.0 - abs((hits[2].w * -r1.w + r0.y));
    r0.z = saturate(r1.x - hits[2].w);
    r0.z = r0.z * r0.y;
    r0.y = r0.y >= 0.0 ? r0.z : 0.0;
    r0.x = r0.y + r0.x;
    r0.yzw = texcoord1.xyz - hits[3].xyz;
    r0.y = dot(r0.yzw, r0.yzw);
    r0.y = 1.0 / rsqrt(abs(r0.y));
    r0.y = 1.0 - abs((hits[3].w * -r1.w + r0.y));
    r0.z = saturate(r1.x - hits[3].w);
    r0.z = r0.z * r0.y;
    r0.y = r0.y >= 0.0 ? r0.z : 0.0;
    r0.x = r0.y + r0.x;
    r0.y = saturate(abs((texcoord3.z * -(1.0 / texcoord3.w) + tex2Dproj(depthMap, texcoord3).x)) * 200.0);
    r2.xyz = normalize((eyeW - texcoord1.xyz));
    r0.z = 1.0 - abs(dot(normalize(texcoord2.xyz), r2.xyz));
    r0.w = r0.z * r0.z;
    r0.y = (r0.z * r0.w - r0.y) + 1.0;
    r1 = tex2D(hexTex, (8.0 * texcoord0.xy));
    r0.x = r0.x * r1.x + r0.y;
    oC0 = (r1.x * 0.05 + r0.x) * shieldColor;
    return oC0;
}
