// oracle: flags=DEBUG
// Debug information with a discard and a branch on a computed value.
sampler2D tex : register(s0);
float cutoff;
float4 main(float2 uv : TEXCOORD0, float4 tint : COLOR0) : COLOR
{
    float4 c = tex2D(tex, uv);
    clip(c.a - cutoff);
    float lum = dot(c.rgb, float3(0.3, 0.59, 0.11));
    if (lum > 0.5)
        c.rgb = lerp(c.rgb, tint.rgb, 0.5);
    else
        c.rgb *= 2;
    return c;
}
