// Spheremap transform (Lambert azimuthal) normal encoding, depth packed in two channels.
sampler2D diffuse_s : register(s0);
float4 gbufParams;   // x = 1/far

float2 encode(float3 n)
{
    float f = sqrt(8 * n.z + 8);
    return n.xy / f + 0.5;
}

float2 packDepth(float d)
{
    float2 enc = float2(1.0, 255.0) * d;
    enc = frac(enc);
    enc.x -= enc.y / 255.0;
    return enc;
}

void main(in float2 uv : TEXCOORD0, in float3 n : TEXCOORD1, in float z : TEXCOORD2,
          out float4 c0 : COLOR0, out float4 c1 : COLOR1, out float4 c2 : COLOR2)
{
    c0 = tex2D(diffuse_s, uv);
    c1 = float4(encode(normalize(n)), packDepth(z * gbufParams.x));
    c2 = float4(z, z * z, 0, 1);
}
