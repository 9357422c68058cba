// Feature toggles as bool uniforms: if b# blocks in the output.
sampler2D diffuse : register(s0);
sampler2D detail  : register(s1);
sampler2D emissiveMap : register(s2);
bool useDetail   : register(b0);
bool useEmissive : register(b1);
bool invert      : register(b2);
float4 emissiveScale;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float4 c = tex2D(diffuse, uv);
    if (useDetail)
        c.rgb *= tex2D(detail, uv * 8).rgb * 2;
    if (useEmissive)
        c.rgb += tex2D(emissiveMap, uv).rgb * emissiveScale.rgb;
    if (invert)
        c.rgb = 1 - c.rgb;
    return c;
}
