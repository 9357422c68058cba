// ps_3_0 shader decompiled by ps30
float4 g_Arr[3] : register(c10);
float4 g_Color : register(c15);
float3x3 g_M33 : register(c4);
float4x3 g_M43 : register(c7);
row_major float4x4 g_RowMat : register(c0);
float4 g_b : register(c17); // the table's type: bool
float g_fKey : register(c16);
float4 g_i : register(c18); // the table's type: int
float4 g_s[2] : register(c13); // the table's type: struct { float4 a; float2 b; }
sampler2D s2d : register(s0);
samplerCUBE scube : register(s1);
sampler3D s3d : register(s2);
sampler2D s1d : register(s3);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1_centroid, float4 color0 : COLOR0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.x = frac(texcoord0.x);
    r0.y = -r0.x >= 0.0 ? 0.0 : 1.0;
    r0.x = texcoord0.x - r0.x;
    r0.y = texcoord0.x >= 0.0 ? 0.0 : r0.y;
    r0.xyz = (r0.y + r0.x) + float3(-0.0, -1.0, -2.0);
    r1 = -abs(r0.x) >= 0.0 ? g_Arr[0] : 0.0;
    r0 = -abs(r0.z) >= 0.0 ? g_Arr[2] : (-abs(r0.y) >= 0.0 ? g_Arr[1] : r1);
    r0 = r0 + texCUBE(scube, texcoord1.xyz);
    r0 = r0 + tex3D(s3d, texcoord1.xyz);
    r0 = r0 + tex2D(s1d, texcoord0.xy);
    r1.xyz = texcoord1.z * g_RowMat[2].xyz + (texcoord1.x * g_RowMat[0].xyz + (g_RowMat[1].xyz * texcoord1.y));
    r1.xyz = (r1.xyz + g_RowMat[3].xyz) + mul(texcoord1.xyz, g_M33);
    r2 = texcoord1.xyzx * float4(1.0, 1.0, 1.0, 0.0) + float4(0.0, 0.0, 0.0, 1.0);
    r1.xyz = r1.xyz + mul(r2, g_M43);
    r2 = tex2D(s2d, texcoord0.xy) * g_Color + g_fKey;
    r2.xyz = r1.xyz + r2.xyz;
    r0 = r0 + r2;
    r0 = -g_b.x >= 0.0 ? r0 : (r0 * g_i.x);
    oC0 = (r0 + (g_s[0] + g_s[1].xyxy)) * color0;
    return oC0;
}
