// half locals and inputs: _pp modifiers on arithmetic and texture loads.
sampler2D baseMap;
float4 tintColor;
float intensity;

half4 main(half2 uv : TEXCOORD0, half3 n : TEXCOORD1) : COLOR
{
    half3 N = normalize(n);
    half4 c = tex2D(baseMap, uv) * tintColor;
    c.rgb *= saturate(N.z) * intensity;
    return c;
}
