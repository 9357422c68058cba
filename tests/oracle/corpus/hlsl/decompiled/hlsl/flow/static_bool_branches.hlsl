// ps_3_0 shader decompiled by ps30
float4 emissiveScale : register(c0);
bool useDetail : register(b0);
bool useEmissive : register(b1);
bool invert : register(b2);
sampler2D diffuse : register(s0);
sampler2D detail : register(s1);
sampler2D emissiveMap : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(diffuse, texcoord0.xy);
    if (useDetail) {
        r1 = tex2D(detail, (8.0 * texcoord0.xy));
        r1.xyz = r0.xyz * r1.xyz;
        r0.xyz = r1.xyz + r1.xyz;
    }
    if (useEmissive) {
        r1 = tex2D(emissiveMap, texcoord0.xy);
        r0.xyz = r1.xyz * emissiveScale.xyz + r0.xyz;
    }
    if (invert) {
        r0.xyz = 1.0 - r0.xyz;
    }
    oC0 = r0;
    return oC0;
}
