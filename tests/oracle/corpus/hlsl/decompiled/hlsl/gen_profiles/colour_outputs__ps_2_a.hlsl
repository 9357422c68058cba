// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)

void main(float4 texcoord0 : TEXCOORD0, float4 color0 : COLOR0, out precise float4 oC0 : COLOR0, out precise float4 oC1 : COLOR1, out precise float oDepth : DEPTH)
{
    oC0 = 0;
    oC1 = 0;
    oDepth = 0;
    oC0 = texcoord0;
    oC1 = color0;
    oDepth = texcoord0.z;
}
