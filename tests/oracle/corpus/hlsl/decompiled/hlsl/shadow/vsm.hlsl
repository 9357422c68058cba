// ps_3_0 shader decompiled by ps30
float bleedReduce : register(c1);
float minVariance : register(c0);
sampler2D momentsMap : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.x = 1.0 / texcoord0.w;
    r1 = tex2D(momentsMap, (r0.x * texcoord0.xy));
    r0.y = texcoord0.z * r0.x - r1.x;
    r0.x = texcoord0.z * -r0.x + r1.x;
    r1.x = max((r1.x * -r1.x + r1.y), minVariance);
    r0.x = r0.x >= 0.0 ? 1.0 : 0.0;
    r0.y = r0.y * r0.y + r1.x;
    r0.y = r1.x * (1.0 / r0.y) - bleedReduce;
    r0.z = 1.0 / (1.0 - bleedReduce);
    r0.y = saturate(r0.z * r0.y);
    oC0 = max(r0.x, r0.y);
    return oC0;
}
