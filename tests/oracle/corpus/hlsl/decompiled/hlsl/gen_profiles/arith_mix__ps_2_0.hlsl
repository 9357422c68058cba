// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30
float4 k : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 color0 : COLOR0) : COLOR
{
    float4 oC0 = 0;
    float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.xyz = rsqrt(abs(dot(texcoord1.xyz, texcoord1.xyz))) * texcoord1.zxy;
    r1.xyz = r0.zxy * k.zxy - (r0.xyz * k.yzx);
    r0.x = saturate(dot(r0.yzx, k.xyz));
    r2.w = pow(abs(r0.x), k.w);
    r0.y = frac(texcoord0.x) + r2.w;
    r0.z = exp2(texcoord0.y);
    r0.y = r0.z + r0.y;
    r0.z = log2(abs((abs(texcoord0.z) + 1.0)));
    r1.w = r0.z + r0.y;
    r2 = lerp(color0, r1, r0.x);
    r0.z = rsqrt(abs((r0.x + 1.0)));
    r1.x = texcoord0.w;
    r3.xy = float2(cos(r1.x), sin(r1.x));
    r0.x = r3.y;
    r0.y = r3.x;
    r0.w = max(texcoord0.x, texcoord0.y);
    oC0 = (r0 + r2);
    return oC0;
}
