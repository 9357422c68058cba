// ps_3_0 shader decompiled by ps30

float4 main(float4 color0 : COLOR0, float4 color1 : COLOR1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    oC0.xyz = color0.xyz + color1.xyz;
    oC0.w = color0.w;
    return oC0;
}
