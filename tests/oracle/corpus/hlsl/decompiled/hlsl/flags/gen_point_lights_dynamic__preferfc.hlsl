// ps_3_0 shader decompiled by ps30
float3 ambient : register(c16);
float4 lightCol[8] : register(c8);
float4 lightPos[8] : register(c0);
int4 lightCount : register(i0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 color0 : COLOR0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    r0.xyz = normalize(texcoord1.xyz);
    r1.xyz = ambient;
    r0.w = 0.0;
    for (int n0 = 0; n0 < lightCount.x; n0++) {
        r2 = r0.w + float4(-0.0, -1.0, -2.0, -3.0);
        r3 = r0.w + float4(-4.0, -5.0, -6.0, -7.0);
        r4.x = 0.0;
        r5 = -abs(r2.y) >= 0.0 ? lightPos[1] : (-abs(r2.x) >= 0.0 ? lightPos[0] : r4.x);
        r5 = -abs(r2.w) >= 0.0 ? lightPos[3] : (-abs(r2.z) >= 0.0 ? lightPos[2] : r5);
        r5 = -abs(r3.y) >= 0.0 ? lightPos[5] : (-abs(r3.x) >= 0.0 ? lightPos[4] : r5);
        r5 = -abs(r3.w) >= 0.0 ? lightPos[7] : (-abs(r3.z) >= 0.0 ? lightPos[6] : r5);
        r4.yzw = r5.xyz - texcoord0.xyz;
        r1.w = dot(r4.yzw, r4.yzw);
        r5.x = rsqrt(abs(r1.w));
        r1.w = 1.0 / (r5.w * r1.w + 1.0);
        r5.yzw = -abs(r2.y) >= 0.0 ? lightCol[1].xyz : (-abs(r2.x) >= 0.0 ? lightCol[0].xyz : r4.x);
        r2.xyz = -abs(r2.z) >= 0.0 ? lightCol[2].xyz : r5.yzw;
        r2.xyz = -abs(r2.w) >= 0.0 ? lightCol[3].xyz : r2.xyz;
        r2.xyz = -abs(r3.y) >= 0.0 ? lightCol[5].xyz : (-abs(r3.x) >= 0.0 ? lightCol[4].xyz : r2.xyz);
        r2.xyz = -abs(r3.w) >= 0.0 ? lightCol[7].xyz : (-abs(r3.z) >= 0.0 ? lightCol[6].xyz : r2.xyz);
        r3.xyz = r4.yzw * r5.x;
        r2.w = dot(r0.xyz, r3.xyz);
        r3.x = max(r2.w, 0.0);
        r2.xyz = r2.xyz * r3.x;
        r1.xyz = r2.xyz * r1.w + r1.xyz;
        r0.w = r0.w + 1.0;
    }
    oC0.xyz = r1.xyz * color0.xyz;
    oC0.w = color0.w;
    return oC0;
}
