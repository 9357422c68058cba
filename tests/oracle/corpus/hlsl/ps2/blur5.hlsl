// oracle: target=ps_2_0
// A five-tap Gaussian along one axis, weights from a uniform array, offsets in texels.
sampler2D src : register(s0);
float4 weights[5];
float2 texel;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 sum = 0;
    for (int i = 0; i < 5; i++)
        sum += tex2D(src, uv + texel * (i - 2)) * weights[i].x;
    return sum;
}
