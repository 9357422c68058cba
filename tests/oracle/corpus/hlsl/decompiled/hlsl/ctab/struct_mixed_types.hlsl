// ps_3_0 shader decompiled by ps30
float4 P[9] : register(c0); // the table's type: struct { bool enabled; int mode; float scale; float3 offset; row_major float3x4 xform; float2x2 rot; }

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0.xy = dot(P[5], texcoord0) * P[8].xy;
    r0.z = dot(P[4], texcoord0);
    r0.xy = P[7].xy * r0.z + r0.xy;
    r0.z = dot(P[6], texcoord0);
    r0.xyz = -P[0].x >= 0.0 ? r0.xyz : (r0.xyz * P[2].x + P[3].xyz);
    r0.w = 1.0;
    oC0 = r0 * (1.0 + P[1].x);
    return oC0;
}
