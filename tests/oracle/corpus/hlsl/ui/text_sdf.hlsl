// Signed-distance-field text with outline and drop shadow; fwidth gives the AA width.
sampler2D fontAtlas : register(s0);
float4 textColor;
float4 outlineColor;
float  outlineWidth = 0.1;
float2 shadowOffset;
float4 shadowColor;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float d = tex2D(fontAtlas, uv).a;
    float w = fwidth(d) * 0.7;
    float fill = smoothstep(0.5 - w, 0.5 + w, d);
    float outl = smoothstep(0.5 - outlineWidth - w, 0.5 - outlineWidth + w, d);
    float4 c = lerp(outlineColor, textColor, fill);
    c.a *= outl;
    float sd = tex2D(fontAtlas, uv - shadowOffset).a;
    float sh = smoothstep(0.5 - w * 4, 0.5 + w * 4, sd) * shadowColor.a;
    return lerp(float4(shadowColor.rgb, sh), c, c.a);
}
