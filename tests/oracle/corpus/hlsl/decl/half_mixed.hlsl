// Mixed half and float: precision changes within one expression chain.
sampler2D tex;
float4 exactScale;
float4 roughScale;

float4 main(float2 uv : TEXCOORD0, half4 vc : COLOR0) : COLOR
{
    half4 h = tex2D(tex, uv) * roughScale;
    float4 f = h * exactScale;
    half l = length(h.rgb);
    return f + vc * l;
}
