// ps_3_0 shader decompiled by ps30
float cutoff : register(c0);
sampler2D tex : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 color0 : COLOR0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0;
    r0 = tex2D(tex, texcoord0.xy);
    r1 = r0.w - cutoff;
    clip(r1);
    r1.x = 0.5 - dot(r0.xyz, float3(0.3, 0.59, 0.11));
    r1.yzw = lerp(r0.xyz, color0.xyz, 0.5);
    oC0.w = r0.w;
    oC0.xyz = r1.x >= 0.0 ? (r0.xyz + r0.xyz) : r1.yzw;
    return oC0;
}
