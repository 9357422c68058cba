// Narkowicz's fitted ACES curve.
sampler2D s_hdr;
float g_Exposure;

half3 ACESFilm(half3 x)
{
    const half a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return saturate((x * (a * x + b)) / (x * (c * x + d) + e));
}

half4 main(half2 uv : TEXCOORD0) : COLOR
{
    half3 col = tex2D(s_hdr, uv).rgb * exp2(g_Exposure);
    return half4(ACESFilm(col), 1);
}
