// All ten interpolator slots: TEXCOORD0-7 and COLOR0-1, summed with weights.
float4 w[10];

float4 main(float4 t0 : TEXCOORD0, float4 t1 : TEXCOORD1, float4 t2 : TEXCOORD2, float4 t3 : TEXCOORD3,
            float4 t4 : TEXCOORD4, float4 t5 : TEXCOORD5, float4 t6 : TEXCOORD6, float4 t7 : TEXCOORD7,
            float4 c0 : COLOR0, float4 c1 : COLOR1) : COLOR
{
    return t0 * w[0] + t1 * w[1] + t2 * w[2] + t3 * w[3] + t4 * w[4]
         + t5 * w[5] + t6 * w[6] + t7 * w[7] + c0 * w[8] + c1 * w[9];
}
