// ps_3_0 shader decompiled by ps30
float bias : register(c22);
float2 noiseScale : register(c20);
float4x4 projection : register(c16);
float radius : register(c21);
float3 samples[16] : register(c0);
sampler2D posVS : register(s0);
sampler2D nrmVS : register(s1);
sampler2D noise : register(s2);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0, r6 = 0, r7 = 0, r8 = 0, r9 = 0, r10 = 0, r11 = 0;
    r0 = tex2D(posVS, texcoord0.xy);
    r2.xyz = normalize(tex2D(nrmVS, texcoord0.xy).xyz);
    r1 = tex2D(noise, (noiseScale * texcoord0.xy));
    r3.xyz = normalize(r1.xyz);
    r0.w = dot(r3.xyz, r2.xyz);
    r3.xyz = normalize((r2.xyz * -r0.w + r3.xyz));
    r1.xyz = r2.yzx * r3.zxy - (r2.zxy * r3.yzx);
    r4.w = 1.0;
    r5.zw = 0.0;
    r6.xy = 0.0;
    for (int n0 = 0; n0 < int4(16, 0, 0, 0).x; n0++) {
        r7 = r6.y + float4(-0.0, -1.0, -2.0, -3.0);
        r8 = r6.y + float4(-4.0, -5.0, -6.0, -7.0);
        r9 = r6.y + float4(-8.0, -9.0, -10.0, -11.0);
        r10 = r6.y + float4(-12.0, -13.0, -14.0, -15.0);
        r11.xyz = -abs(r7.y) >= 0.0 ? samples[1] : (-abs(r7.x) >= 0.0 ? samples[0] : 0.0);
        r7.xyz = -abs(r7.z) >= 0.0 ? samples[2] : r11.xyz;
        r7.xyz = -abs(r7.w) >= 0.0 ? samples[3] : r7.xyz;
        r7.xyz = -abs(r8.y) >= 0.0 ? samples[5] : (-abs(r8.x) >= 0.0 ? samples[4] : r7.xyz);
        r7.xyz = -abs(r8.w) >= 0.0 ? samples[7] : (-abs(r8.z) >= 0.0 ? samples[6] : r7.xyz);
        r7.xyz = -abs(r9.y) >= 0.0 ? samples[9] : (-abs(r9.x) >= 0.0 ? samples[8] : r7.xyz);
        r7.xyz = -abs(r9.w) >= 0.0 ? samples[11] : (-abs(r9.z) >= 0.0 ? samples[10] : r7.xyz);
        r7.xyz = -abs(r10.y) >= 0.0 ? samples[13] : (-abs(r10.x) >= 0.0 ? samples[12] : r7.xyz);
        r7.xyz = -abs(r10.w) >= 0.0 ? samples[15] : (-abs(r10.z) >= 0.0 ? samples[14] : r7.xyz);
        r8.xyz = r1.xyz * r7.y;
        r7.xyw = r7.x * r3.xyz + r8.xyz;
        r4.xyz = (r7.z * r2.xyz + r7.xyw) * radius + r0.xyz;
        r7.x = dot(r4, projection._m00_m10_m20_m30);
        r7.y = dot(r4, projection._m01_m11_m21_m31);
        r4.xy = (1.0 / dot(r4, projection._m03_m13_m23_m33)) * r7.xy;
        r5.xy = r4.xy * float2(0.5, -0.5) + 0.5;
        r7 = tex2Dlod(posVS, r5);
        r0.w = r0.z - r7.z;
        r0.w = saturate((1.0 / abs(r0.w)) * radius);
        r1.w = r0.w * -2.0 + 3.0;
        r0.w = (r0.w * r0.w) * r1.w;
        r1.w = r7.z - (r4.z + bias);
        r0.w = r1.w >= 0.0 ? r0.w : 0.0;
        r6.x = r0.w + r6.x;
        r6.y = r6.y + 1.0;
    }
    oC0 = r6.x * -0.0625 + 1.0;
    return oC0;
}
