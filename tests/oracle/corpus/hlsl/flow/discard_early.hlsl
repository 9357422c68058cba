// discard in a branch (texkill), then lighting.
sampler2D alphaMask;
sampler2D col;
float cutoff;

float4 main(float2 uv : TEXCOORD0, float3 n : TEXCOORD1) : COLOR
{
    if (tex2D(alphaMask, uv).a < cutoff)
        discard;
    return tex2D(col, uv) * saturate(n.z);
}
