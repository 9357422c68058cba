// Refused by D3DCompile (X3528): a forced [branch] around tex2D whose coordinates are computed
// in the shader (uv * detailTile) needs gradients inside the branch. surface/terrain_lod_detail.hlsl
// is the fixed version (gradients taken before the branch, tex2Dgrad inside).
// Terrain far/near blend: macro colour texture far away, detail layers near.
sampler2D macroColor;
sampler2D detailA;
sampler2D detailB;
sampler2D blendMask;
float4 detailFade;   // x start, y 1/range
float  detailTile;

float4 main(float2 uv : TEXCOORD0, float dist : TEXCOORD1) : COLOR
{
    float4 macro = tex2D(macroColor, uv);
    float near = 1 - saturate((dist - detailFade.x) * detailFade.y);
    float4 d;
    [branch]
    if (near > 0)
    {
        float m = tex2D(blendMask, uv).r;
        d = lerp(tex2D(detailA, uv * detailTile), tex2D(detailB, uv * detailTile), m);
    }
    else
        d = 0.5;
    return macro * lerp(1, d * 2, near);
}
