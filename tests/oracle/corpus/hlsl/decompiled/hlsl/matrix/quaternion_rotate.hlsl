// ps_3_0 shader decompiled by ps30
float4 rotationQ : register(c0);
float3 translation : register(c1);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0.xyz = rotationQ.w * texcoord0.yzx + (rotationQ.zxy * texcoord0.xyz - (rotationQ.xyz * texcoord0.zxy));
    r1.xyz = r0.xyz * rotationQ.zxy;
    r0.xyz = (rotationQ.yzx * r0.yzx - r1.xyz) * 2.0 + texcoord0.xyz;
    r1.xyz = rotationQ.w * texcoord1.yzx + (rotationQ.zxy * texcoord1.xyz - (rotationQ.xyz * texcoord1.zxy));
    r1.xyz = rotationQ.yzx * r1.yzx - (r1.xyz * rotationQ.zxy);
    oC0.xyz = (r0.xyz + translation) * 0.01 + (r1.xyz * 2.0 + texcoord1.xyz);
    oC0.w = 1.0;
    return oC0;
}
