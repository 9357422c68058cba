// Terrain far/near blend: macro colour texture far away, detail layers near. The detail
// fetches sit in a real branch, so their gradients are taken before it.
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
    float2 duv = uv * detailTile;
    float2 gx = ddx(duv), gy = ddy(duv);
    float4 d;
    [branch]
    if (near > 0)
    {
        float m = tex2D(blendMask, uv).r;
        d = lerp(tex2Dgrad(detailA, duv, gx, gy), tex2Dgrad(detailB, duv, gx, gy), m);
    }
    else
        d = 0.5;
    return macro * lerp(1, d * 2, near);
}
