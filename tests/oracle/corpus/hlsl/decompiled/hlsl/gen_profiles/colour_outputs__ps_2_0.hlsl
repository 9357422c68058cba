// oracle: target=ps_2_0
// ps_2_0 shader decompiled by ps30

void main(float4 texcoord0 : TEXCOORD0, float4 color0 : COLOR0, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1, out precise float oDepth : DEPTH)
{
    oC0 = 0;
    oC1 = 0;
    oDepth = 0;
    oC0 = texcoord0;
    oC1 = color0;
    oDepth = texcoord0.z;
}
