// Names longer than the listing's 12-character Name column, and one exactly 12 long.
float4 g_vMaterialDiffuseColorAndOpacity;
float4 abcdefghijkl;            // exactly twelve
float4 x;
sampler2D g_samplerDiffuseAlbedoWithAlpha;

float4 main(float2 uv : TEXCOORD0) : COLOR
{
    return tex2D(g_samplerDiffuseAlbedoWithAlpha, uv) * g_vMaterialDiffuseColorAndOpacity
         + abcdefghijkl * x;
}
