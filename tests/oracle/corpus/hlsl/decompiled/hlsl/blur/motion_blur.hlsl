// ps_3_0 shader decompiled by ps30
float4x4 currInvViewProj : register(c0);
float4 numSamples : register(c8); // the table's type: int
float4x4 prevViewProj : register(c4);
sampler2D frame : register(s0);
sampler2D depth : register(s1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0;
    r1.xyw = texcoord0.xyx * float3(2.0, -2.0, 0.0) + float2(-1.0, 1.0).xyy;
    r1.z = tex2D(depth, texcoord0.xy).x;
    r0 = mul(r1, currInvViewProj);
    r0 = r0 * (1.0 / r0.w);
    r1.x = dot(r0, prevViewProj._m00_m10_m20_m30);
    r1.y = dot(r0, prevViewProj._m01_m11_m21_m31);
    r0.x = 1.0 / dot(r0, prevViewProj._m03_m13_m23_m33);
    r0.yz = texcoord0.xy * float2(2.0, -2.0) + float2(-1.0, 1.0);
    r0.xy = (r1.xy * -r0.x + r0.yz) * 0.5;
    r1 = tex2D(frame, texcoord0.xy);
    r0.w = 1.0 / numSamples.x;
    r0.z = -r0.y;
    r2.zw = 0.0;
    r3 = r1;
    r2.xy = texcoord0.xy;
    r0.y = 1.0;
    for (int n0 = 0; n0 < int4(255, 0, 0, 0).x; n0++) {
        if (r0.y >= numSamples.x) break;
        r2.xy = r0.xz * r0.w + r2.xy;
        r4 = tex2Dlod(frame, r2);
        r3 = r3 + r4;
        r0.y = r0.y + 1.0;
    }
    oC0 = r0.w * r3;
    return oC0;
}
