// 13-tap downsample with Karis average to kill fireflies (first mip only).
sampler2D Src;
float2 TexelSize;

float KarisWeight(float3 c) { return 1 / (1 + dot(c, float3(0.299, 0.587, 0.114))); }

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float2 t = TexelSize;
    float3 a = tex2D(Src, uv + t * float2(-1, -1)).rgb;
    float3 b = tex2D(Src, uv + t * float2( 1, -1)).rgb;
    float3 c = tex2D(Src, uv + t * float2(-1,  1)).rgb;
    float3 d = tex2D(Src, uv + t * float2( 1,  1)).rgb;
    float3 e = tex2D(Src, uv).rgb;
    float wa = KarisWeight(a), wb = KarisWeight(b), wc = KarisWeight(c), wd = KarisWeight(d), we = KarisWeight(e);
    float3 sum = a * wa + b * wb + c * wc + d * wd + e * we * 4;
    return float4(sum / (wa + wb + wc + wd + we * 4), 1);
}
