// ps_3_0 shader decompiled by ps30
float atlasBias[3] : register(c11);
float4 cascadeMatrix[11] : register(c0); // the table's type: float4x4[3]
float3 cascadeSplits : register(c14);
sampler2D cascadeAtlas : register(s4);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0;
    r0.y = 0.5;
    r0.zw = texcoord1.x - cascadeSplits.yx;
    r0.z = r0.z >= 0.0 ? 2.0 : 1.0;
    r0.z = r0.w >= 0.0 ? r0.z : 0.0;
    r1 = r0.z + float4(-0.0, -1.0, -2.0, 0.5);
    oC0.y = r0.z * 0.5;
    r0.z = 0.0;
    r2 = -abs(r1.y) >= 0.0 ? cascadeMatrix[4] : (-abs(r1.x) >= 0.0 ? cascadeMatrix[0] : r0.z);
    r2.x = dot(texcoord0, (-abs(r1.z) >= 0.0 ? cascadeMatrix[8] : r2));
    r3 = -abs(r1.y) >= 0.0 ? cascadeMatrix[5] : (-abs(r1.x) >= 0.0 ? cascadeMatrix[1] : r0.z);
    r2.y = dot(texcoord0, (-abs(r1.z) >= 0.0 ? cascadeMatrix[9] : r3));
    r0.x = r1.w * 0.33333334;
    r2 = tex2D(cascadeAtlas, (r2.xy * float2(0.16666667, -0.5) + r0.xy));
    r3 = -abs(r1.y) >= 0.0 ? cascadeMatrix[6] : (-abs(r1.x) >= 0.0 ? cascadeMatrix[2] : r0.z);
    r0.x = dot(texcoord0, (-abs(r1.z) >= 0.0 ? cascadeMatrix[10] : r3));
    r0.y = -abs(r1.x) >= 0.0 ? atlasBias[0] : r0.z;
    r0.y = -abs(r1.z) >= 0.0 ? atlasBias[2] : (-abs(r1.y) >= 0.0 ? atlasBias[1] : r0.y);
    r0.x = r0.x - r0.y;
    oC0.x = (r0.x - r2.x) >= 0.0 ? 0.0 : 1.0;
    oC0.zw = float2(0.0, 1.0);
    return oC0;
}
