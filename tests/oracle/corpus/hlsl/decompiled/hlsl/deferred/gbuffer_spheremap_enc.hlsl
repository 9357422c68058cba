// ps_3_0 shader decompiled by ps30
float4 gbufParams : register(c0);
sampler2D diffuse_s : register(s0);

void main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1, out precise float4 oC2 : COLOR2)
{
    precise float4 r0 = 0;
    oC0 = 0;
    oC1 = 0;
    oC2 = 0;
    oC0 = tex2D(diffuse_s, texcoord0.xy);
    r0.xyz = normalize(texcoord1.xyz);
    r0.z = rsqrt(abs((r0.z * 8.0 + 8.0)));
    oC1.xy = r0.xy * r0.z + 0.5;
    r0.xy = frac(((gbufParams.x * texcoord2.x) * float2(1.0, 255.0)));
    oC1.z = r0.y * -0.003921569 + r0.x;
    oC1.w = r0.y;
    oC2.y = texcoord2.x * texcoord2.x;
    oC2.xzw = texcoord2.x * float3(1.0, 0.0, 0.0) + float3(0.0, 0.0, 1.0);
}
