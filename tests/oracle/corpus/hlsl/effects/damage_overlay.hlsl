// HUD damage: red vignette pulse and blood splatter texture, plus desaturation.
sampler2D sceneS : register(s0);
sampler2D splatS : register(s1);
float damage;
float pulse;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    float3 c = tex2D(sceneS, uv).rgb;
    float g = dot(c, 0.333);
    c = lerp(c, g.xxx, damage * 0.6);
    float v = smoothstep(0.3, 0.8, length(uv - 0.5)) * (0.6 + 0.4 * pulse) * damage;
    float4 s = tex2D(splatS, uv);
    c = lerp(c, float3(0.6, 0, 0), saturate(v + s.a * damage));
    return float4(c, 1);
}
