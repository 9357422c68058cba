// ps_3_0 shader decompiled by ps30

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.xy = texcoord0.xy;
    r0.z = dot(r0.xxyy, texcoord1.xxyy);
    oC0 = texcoord1.xyxy * -r0.z + r0.xyxy;
    return oC0;
}
