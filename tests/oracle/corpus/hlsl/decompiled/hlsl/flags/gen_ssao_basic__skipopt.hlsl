// ps_3_0 shader decompiled by ps30
float DepthScale : register(c2);
float SampleRadius : register(c1);
float4 ScreenParams : register(c0);
sampler2D DepthSampler : register(s0);
sampler2D RandomSampler : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    r0.x = tex2D(DepthSampler, texcoord0.xy).x;
    r1 = tex2D(RandomSampler, (ScreenParams.xy * texcoord0.xy));
    r0.yzw = (r1.xyz * 2.0) - 1.0;
    r1.xy = 0.0;
    for (int n0 = 0; n0 < int4(8, 0, 0, 0).x; n0++) {
        r2 = abs((r1.y + float4(-0.0, -1.0, -2.0, -3.0)));
        r3 = abs((r1.y + float4(-4.0, -5.0, -6.0, -7.0)));
        r4 = -r2;
        r5 = -r3;
        r1.z = ((-r2.x) + r4.x) >= 0.0 ? 1.0 : 0.0;
        r1.w = (-r2.y) + r4.y;
        r2.x = -r2.z;
        r2.x = (r2.x + r4.z) >= 0.0 ? 1.0 : 0.0;
        r2.y = -r2.w;
        r2.y = (r2.y + r4.w) >= 0.0 ? 1.0 : 0.0;
        r3 = -r3;
        r3 = (r3 + r5) >= 0.0 ? 1.0 : 0.0;
        r4.xyz = (-r1.z).xxx >= 0.0 ? 0.0 : float3(0.355512, -0.709318, -0.102371);
        r5.xyz = -(r1.w >= 0.0 ? 1.0 : 0.0);
        r2.xzw = (-r2.x).xxx >= 0.0 ? (r5.xyz >= 0.0 ? r4.xyz : float3(0.534186, 0.71511, -0.115167)) : float3(-0.87866, 0.157139, -0.115167);
        r2.xyz = (-r2.y).xxx >= 0.0 ? r2.xzw : float3(0.140679, -0.475516, -0.0639818);
        r2.xyz = (-r3.x).xxx >= 0.0 ? r2.xyz : float3(-0.0796121, 0.158842, -0.677075);
        r4.xyz = -r3.y;
        r2.xyz = (-r3.z).xxx >= 0.0 ? (r4.xyz >= 0.0 ? r2.xyz : float3(-0.0759516, -0.101676, -0.483625)) : float3(0.12493, -0.0223423, -0.483625);
        r3.xyz = -r3.w;
        r2.xyz = r3.xyz >= 0.0 ? r2.xyz : float3(-0.0720074, 0.243395, -0.967251);
        r1.z = dot(r2.xyz, r0.yzw);
        r1.z = -(r1.z + r1.z);
        r1.zw = r2.xy + (r0.yz * r1.z);
        r2.x = 1.0 / r0.x;
        r2.y = 1.0 / r0.x;
        r1.zw = (r1.zw * SampleRadius) * r2.xy;
        r2 = tex2D(DepthSampler, (r1.zw + texcoord0.xy));
        r1.z = (r0.x + (-r2.x)) * DepthScale;
        r1.w = (r1.z - 0.02) >= 0.0 ? 1.0 : 0.0;
        r1.z = (r1.z - 0.5) * 0.6666667;
        r1.z = (r1.z - 0.0) >= 0.0 ? r1.z : 0.0;
        r1.z = (r1.z - 1.0) >= 0.0 ? 1.0 : r1.z;
        r2.x = (r1.z * -2.0) + 3.0;
        r1.z = (r1.z * r1.z) * r2.x;
        r1.z = (-r1.z) + 1.0;
        r1.z = r1.z * r1.w;
        r1.x = r1.z + r1.x;
        r1.y = r1.y + 1.0;
    }
    oC0 = (-(r1.x * 0.125)) + 1.0;
    return oC0;
}
