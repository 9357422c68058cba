// Circular minimap: rotated lookup, circular mask, player marker.
sampler2D mapTex : register(s0);
sampler2D iconTex : register(s1);
float2 playerUV;
float  heading;
float  zoom;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float2 c = uv * 2 - 1;
    clip(1 - dot(c, c));
    float s = sin(heading), co = cos(heading);
    float2 r = float2(c.x * co - c.y * s, c.x * s + c.y * co);
    float4 m = tex2D(mapTex, playerUV + r * zoom);
    float4 icon = tex2D(iconTex, uv * 8 - 3.5);
    float edge = smoothstep(0.9, 1.0, length(c));
    m.rgb = lerp(m.rgb, icon.rgb, icon.a * all(abs(c) < 0.0625 * 2));
    return float4(lerp(m.rgb, 0, edge), 1);
}
