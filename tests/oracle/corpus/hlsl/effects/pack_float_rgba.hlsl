// Pack a [0,1) float into RGBA8 and unpack it again (shadow maps on old hardware).
sampler2D packedDepth;

float4 Pack(float v)
{
    float4 enc = float4(1.0, 255.0, 65025.0, 16581375.0) * v;
    enc = frac(enc);
    enc -= enc.yzww * float4(1.0 / 255.0, 1.0 / 255.0, 1.0 / 255.0, 0.0);
    return enc;
}
float Unpack(float4 rgba) { return dot(rgba, float4(1.0, 1 / 255.0, 1 / 65025.0, 1 / 16581375.0)); }

float4 main(float2 uv : TEXCOORD0, float depth : TEXCOORD1) : COLOR
{
    float stored = Unpack(tex2D(packedDepth, uv));
    return Pack(min(stored, depth));
}
