// LOD cross-fade with screen-door dithering (clip against a VPOS pattern).
sampler2D albedoMap;
float lodFade;      // 0..1, negative for the incoming LOD

float4 main(float2 uv : TEXCOORD0, float2 sp : VPOS) : COLOR
{
    float2 q = frac(sp * 0.5);
    float pattern = q.x * 0.5 + q.y * 0.25 + frac(sp.x * 0.25 + sp.y * 0.125) * 0.125;
    float f = lodFade < 0 ? 1 + lodFade : lodFade;
    clip(lodFade < 0 ? f - pattern : pattern - (1 - f));
    return tex2D(albedoMap, uv);
}
