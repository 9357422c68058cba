// Default values on a matrix, an array of vectors and a struct.
struct Wave { float amp; float freq; float2 dir; };
float3x3 ColourMatrix = { 0.393, 0.769, 0.189, 0.349, 0.686, 0.168, 0.272, 0.534, 0.131 };
float4 Weights[3] = { float4(1, 2, 3, 4), float4(5, 6, 7, 8), float4(9, 10, 11, 12) };
Wave W = { 0.5, 2.0, float2(1, 0) };
sampler2D Image;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float3 c = mul(tex2D(Image, uv + W.dir * sin(uv.x * W.freq) * W.amp).rgb, ColourMatrix);
    return float4(c, 1) * (Weights[0] + Weights[1] * uv.x + Weights[2] * uv.y);
}
