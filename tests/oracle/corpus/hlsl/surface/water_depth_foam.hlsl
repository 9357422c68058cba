// Shore foam and depth-based colour using the scene depth behind the water.
sampler2D sceneDepth : register(s0);
sampler2D foamTex    : register(s1);
float4 shallowColor, deepColor;
float depthFade = 2.0;
float foamEdge = 0.4;
float time;

float4 main(float2 uv : TEXCOORD0, float4 screenPos : TEXCOORD1, float waterDepth : TEXCOORD2) : COLOR
{
    float sceneZ = tex2Dproj(sceneDepth, screenPos).r;
    float diff = sceneZ - waterDepth;
    float t = saturate(diff / depthFade);
    float4 c = lerp(shallowColor, deepColor, t);
    float foam = tex2D(foamTex, uv * 4 + time * 0.05).r;
    float edge = 1 - saturate(diff / foamEdge);
    c.rgb += step(1 - edge, foam) * edge;
    c.a = saturate(diff * 4);
    return c;
}
