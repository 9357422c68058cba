// ps_3_0 shader decompiled by ps30
float4 on : register(c0); // the table's type: bool
float4 x : register(c1);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0 = -on.x >= 0.0 ? texcoord0 : (x * texcoord0);
    return oC0;
}
