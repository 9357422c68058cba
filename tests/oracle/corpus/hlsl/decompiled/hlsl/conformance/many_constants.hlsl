// ps_3_0 shader decompiled by ps30
float4 weights[40] : register(c0);
sampler2D image : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = (weights[0] + weights[1]) + weights[2];
    r0 = (r0 + weights[3]) + weights[4];
    r0 = (r0 + weights[5]) + weights[6];
    r0 = (r0 + weights[7]) + weights[8];
    r0 = (r0 + weights[9]) + weights[10];
    r0 = (r0 + weights[11]) + weights[12];
    r0 = (r0 + weights[13]) + weights[14];
    r0 = (r0 + weights[15]) + weights[16];
    r0 = (r0 + weights[17]) + weights[18];
    r0 = (r0 + weights[19]) + weights[20];
    r0 = (r0 + weights[21]) + weights[22];
    r0 = (r0 + weights[23]) + weights[24];
    r0 = (r0 + weights[25]) + weights[26];
    r0 = (r0 + weights[27]) + weights[28];
    r0 = (r0 + weights[29]) + weights[30];
    r0 = (r0 + weights[31]) + weights[32];
    r0 = (r0 + weights[33]) + weights[34];
    r0 = (r0 + weights[35]) + weights[36];
    r0 = (r0 + weights[37]) + weights[38];
    oC0 = (r0 + weights[39]) * tex2D(image, texcoord0.xy);
    return oC0;
}
