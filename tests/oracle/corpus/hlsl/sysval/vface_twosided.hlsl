// Two-sided material: different textures on the front and back face.
sampler2D frontTex : register(s0);
sampler2D backTex  : register(s1);

float4 main(float2 uv : TEXCOORD0, float vface : VFACE) : COLOR
{
    return vface >= 0 ? tex2D(frontTex, uv) : tex2D(backTex, uv);
}
