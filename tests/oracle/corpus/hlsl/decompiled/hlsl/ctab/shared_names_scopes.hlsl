// ps_3_0 shader decompiled by ps30
float4 color : register(c2);
float4 light[2] : register(c0); // the table's type: struct { float4 color; float4 position; }
float4 position : register(c3);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = color * light[0] + ((position - texcoord0) * 0.1);
    oC0 = r0 + (light[1] - texcoord0);
    return oC0;
}
