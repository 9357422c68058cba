// Blend of four float4x4 palette entries in a loop, row_major.
row_major float4x4 Palette[8];

float4 main(float4 v : TEXCOORD0, float4 w : TEXCOORD1, float4 bi : TEXCOORD2) : COLOR
{
    float4 r = 0;
    float wts[4] = (float[4])w;
    float ind[4] = (float[4])bi;
    for (int i = 0; i < 4; i++)
        r += mul(v, Palette[(int)ind[i]]) * wts[i];
    return r;
}
