// oracle: target=ps_2_b
// ps_2_b: more arithmetic than ps_2_0's 64 slots (a polynomial tone curve per channel and a
// film grain hash).
sampler2D hdr : register(s0);
float exposure;
float4 curve[4];

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float3 c = tex2D(hdr, uv).rgb * exposure;
    float3 x = c / (1 + c);
    float3 y = curve[0].xyz;
    for (int k = 1; k < 4; k++)
        y = y * x + curve[k].xyz;
    float3 g = frac(sin(dot(uv, float2(12.9898, 78.233))) * 43758.5453);
    float3 z = y;
    for (int j = 0; j < 6; j++)
        z = z * 0.97 + y * 0.03 + g * 0.001;
    return float4(saturate(z), 1);
}
