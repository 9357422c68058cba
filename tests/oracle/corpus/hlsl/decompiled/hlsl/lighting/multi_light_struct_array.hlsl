// ps_3_0 shader decompiled by ps30
float4 lights[12] : register(c0); // the table's type: struct { float4 pos; float4 color; }[6]
int4 numLights : register(i0);
sampler2D tex0 : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
    r0.xyz = normalize(texcoord2.xyz);
    r1.xyz = 0.0;
    r2.x = 0.0;
    for (int n0 = 0; n0 < numLights.x; n0++) {
        r3 = r2.x + float4(-2.0, -3.0, -4.0, -5.0);
        r2.xyz = r2.x + float3(1.0, -0.0, -1.0);
        r4.x = 0.0;
        r5 = -abs(r2.y) >= 0.0 ? lights[0] : r4.x;
        r5 = -abs(r2.z) >= 0.0 ? lights[2] : r5;
        r2.yzw = -abs(r2.z) >= 0.0 ? lights[3].xyz : (-abs(r2.y) >= 0.0 ? lights[1].xyz : r4.x);
        r4 = -abs(r3.y) >= 0.0 ? lights[6] : (-abs(r3.x) >= 0.0 ? lights[4] : r5);
        r2.yzw = -abs(r3.y) >= 0.0 ? lights[7].xyz : (-abs(r3.x) >= 0.0 ? lights[5].xyz : r2.yzw);
        r4 = -abs(r3.w) >= 0.0 ? lights[10] : (-abs(r3.z) >= 0.0 ? lights[8] : r4);
        r2.yzw = -abs(r3.w) >= 0.0 ? lights[11].xyz : (-abs(r3.z) >= 0.0 ? lights[9].xyz : r2.yzw);
        r5.xyz = normalize((r4.xyz - texcoord1.xyz));
        r3.xyz = -abs(r4.w) >= 0.0 ? r4.xyz : r5.xyz;
        r0.w = saturate(dot(r0.xyz, r3.xyz));
        r1.xyz = r2.yzw * r0.w + r1.xyz;
    }
    r1.w = 1.0;
    oC0 = tex2D(tex0, texcoord0.xy) * r1;
    return oC0;
}
