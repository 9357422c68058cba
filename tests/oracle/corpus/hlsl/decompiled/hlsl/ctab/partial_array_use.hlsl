// ps_3_0 shader decompiled by ps30
float4 bigArray[64] : register(c14);
float4 matArray[8] : register(c0); // the table's type: float4x4[8]
float4 scalarArray[6] : register(c8); // the table's type: float[16]

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0.x = dot(texcoord0, matArray[4]);
    r0.y = dot(texcoord0, matArray[5]);
    r0.z = dot(texcoord0, matArray[6]);
    r0.w = dot(texcoord0, matArray[7]);
    oC0 = (bigArray[2] * texcoord0 + r0) + scalarArray[5].x;
    return oC0;
}
