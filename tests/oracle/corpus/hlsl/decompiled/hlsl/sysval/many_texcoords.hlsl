// ps_3_0 shader decompiled by ps30
float4 w[10] : register(c0);

float4 main(float4 texcoord0 : TEXCOORD0, float4 texcoord1 : TEXCOORD1, float4 texcoord2 : TEXCOORD2, float4 texcoord3 : TEXCOORD3, float4 texcoord4 : TEXCOORD4, float4 texcoord5 : TEXCOORD5, float4 texcoord6 : TEXCOORD6, float4 texcoord7 : TEXCOORD7, float4 color0 : COLOR0, float4 color1 : COLOR1) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0;
    r0 = texcoord0 * w[0] + (w[1] * texcoord1);
    r0 = texcoord3 * w[3] + (texcoord2 * w[2] + r0);
    r0 = texcoord5 * w[5] + (texcoord4 * w[4] + r0);
    r0 = texcoord7 * w[7] + (texcoord6 * w[6] + r0);
    oC0 = color1 * w[9] + (color0 * w[8] + r0);
    return oC0;
}
