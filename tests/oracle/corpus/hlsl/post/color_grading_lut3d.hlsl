// Colour grading through a 16^3 volume LUT with half-texel scale/offset.
sampler2D  sceneTex : register(s0);
sampler3D  gradingLUT : register(s1);
float lutSize = 16;
float lutBlend = 1;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 c = tex2D(sceneTex, uv);
    float3 lutUV = saturate(c.rgb) * ((lutSize - 1) / lutSize) + 0.5 / lutSize;
    float3 graded = tex3D(gradingLUT, lutUV).rgb;
    return float4(lerp(c.rgb, graded, lutBlend), c.a);
}
