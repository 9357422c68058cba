// ps_3_0 shader decompiled by ps30
sampler2D bumpMap : register(s0);
sampler2D diffuseMap : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xyz = normalize(texcoord2.xyz);
    r1.xy = tex2D(bumpMap, texcoord0.xy).wy * 2.0 - 1.0;
    r1.w = max((dot(r1.xy, -r1.xy) + 1.0), 0.0);
    r1.z = 1.0 / rsqrt(abs(r1.w));
    r1.w = pow(abs(saturate(dot(r1.xyz, r0.xyz))), 48.0);
    r0.x = saturate(dot(r1.xyz, normalize(texcoord1.xyz)));
    r0.y = r0.x * r1.w;
    oC0 = tex2D(diffuseMap, texcoord0.xy) * r0.x + r0.y;
    return oC0;
}
