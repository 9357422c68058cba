// Depth-of-field gather: circle of confusion from depth scales a 12-tap disk.
sampler2D colorSamp : register(s0);
sampler2D depthSamp : register(s1);
float focusDist, focusRange, maxCoC;
float2 texSize;

static const float2 disk[12] = {
    float2(-0.326, -0.406), float2(-0.840, -0.074), float2(-0.696,  0.457),
    float2(-0.203,  0.621), float2( 0.962, -0.195), float2( 0.473, -0.480),
    float2( 0.519,  0.767), float2( 0.185, -0.893), float2( 0.507,  0.064),
    float2( 0.896,  0.412), float2(-0.322, -0.933), float2(-0.792, -0.598) };

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float depth = tex2D(depthSamp, uv).r;
    float coc = saturate(abs(depth - focusDist) / focusRange) * maxCoC;
    float4 c = tex2D(colorSamp, uv);
    for (int i = 0; i < 12; i++)
        c += tex2D(colorSamp, uv + disk[i] * texSize * coc);
    return c / 13;
}
