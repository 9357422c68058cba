// Refused by D3DCompile (X3650): a global uniform of type half is an error for ps_3_0 unless
// ENABLE_BACKWARDS_COMPATIBILITY is given (flags/half_globals_compat.hlsl is this shader with
// that flag; decl/half_precision.hlsl keeps half only for locals).
// half throughout: _pp modifiers on arithmetic and texture loads.
sampler2D baseMap;
half4 tintColor;
half  intensity;

half4 main(half2 uv : TEXCOORD0, half3 n : TEXCOORD1) : COLOR
{
    half3 N = normalize(n);
    half4 c = tex2D(baseMap, uv) * tintColor;
    c.rgb *= saturate(N.z) * intensity;
    return c;
}
