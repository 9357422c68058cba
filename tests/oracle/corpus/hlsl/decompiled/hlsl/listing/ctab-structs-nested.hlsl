// ps_3_0 shader decompiled by ps30
float4 g_Lights[7] : register(c8); // the table's type: struct { float3 pos; float4 col; float r; }[3]
float4x4 g_M : register(c22);
float2x2 g_M22 : register(c33);
float4 g_O[7] : register(c15); // the table's type: struct { struct { float2 a; float b; } in1; float4 m; struct { float2 a; float b; } arr[2]; }
row_major float3x4 g_R34 : register(c30);
float4 g_arr[4] : register(c26); // the table's type: float[5]
float4 g_b4 : register(c41);
float4 g_bb[2] : register(c35); // the table's type: bool[2]
float1 g_f1 : register(c37);
float2 g_f2 : register(c40);
float4 g_h4 : register(c38);
float4 g_i4 : register(c39);
float4x4 g_mats[2] : register(c0);
sampler2D g_Samp : register(s0);
sampler2D g_plain : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r0 = g_O[0].xy.xyxy + g_O[2];
    r0 = (r0 + g_O[6].x) + (g_Lights[1] * g_Lights[5].x + g_Lights[6].xyzx);
    r1.xyz = texcoord0.xyx * float3(1.0, 1.0, 0.0) + float3(0.0, 0.0, 1.0);
    r2.x = dot(r1.xyz, g_M._m00_m10_m30);
    r2.y = dot(r1.xyz, g_M._m01_m11_m31);
    r2.z = dot(r1.xyz, g_M._m02_m12_m32);
    r2.w = dot(r1.xyz, g_M._m03_m13_m33);
    r0 = r0 + r2;
    r1 = (g_f1 + g_f2.xyxy) + g_h4;
    r2 = texcoord0.xyxx * float4(1.0, 1.0, 0.0, 0.0) + float4(0.0, 0.0, 1.0, 1.0);
    r0.xyz = r0.xyz + mul(g_R34, r2);
    r3.y = 0.0;
    r4.x = dot(texcoord0.xy, g_M22._m00_m10) + r3.y;
    r4.y = dot(texcoord0.xy, g_M22._m01_m11) + r3.y;
    r0.xy = r0.xy + r4.xy;
    r0 = (r1 + g_i4) + r0;
    r0 = -g_b4.y >= 0.0 ? r0 : (r0 + 1.0);
    r0 = -g_bb[1].x >= 0.0 ? r0 : (r0 + r0);
    r1.x = g_arr[3].x + g_arr[0].x;
    r0 = r0 + (r1.x + mul(r2, g_mats[1]));
    oC0 = r0 + (tex2D(g_Samp, texcoord0.xy) + tex2D(g_plain, texcoord0.xy));
    return oC0;
}
